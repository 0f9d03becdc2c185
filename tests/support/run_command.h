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

// Runs argv[0] (a path, or a name looked up on PATH) with the arguments, without a shell, and
// with `environment` ("NAME=value") set on top of this process's environment; `work_dir` holds
// the captured streams.
CommandResult runProgram(const std::vector<std::string>& argv,
                         const std::filesystem::path& work_dir,
                         const std::vector<std::string>& environment = {});

// runProgram of the gibench binary. The command runs with GIBENCH_GL_DEBUG=1 (a GL error fails
// it) and `environment` added.
CommandResult runGibench(const std::vector<std::string>& args,
                         const std::filesystem::path& work_dir,
                         const std::vector<std::string>& environment = {});

// Number of lines in `text` (a final line without '\n' counts).
int countLines(const std::string& text);

}  // namespace gib::test
