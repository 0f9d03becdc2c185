// Runs the gibench binary as a user would, capturing exit code, stdout and stderr.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace gib::test {

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Arguments are passed without a shell; `work_dir` holds the captured streams.
CommandResult runGibench(const std::vector<std::string>& args,
                         const std::filesystem::path& work_dir);

// Number of lines in `text` (a final line without '\n' counts).
int countLines(const std::string& text);

}  // namespace gib::test
