// Running another program and waiting for it: `gibench diff --confirm` runs the base and the new
// build alternately, and the tests run the command line as a user would. No shell is involved.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace gib {

struct ProgramResult {
  int exit_code = -1;  // 128 + the signal when it was killed
  std::string out;
  std::string err;
};

// Runs argv[0] (a path, or a name looked up on PATH) with the arguments and `environment`
// ("NAME=value", replacing inherited variables of the same name), its output captured through
// files in `work_dir`. Throws std::runtime_error when the program cannot be started.
ProgramResult runProgram(const std::vector<std::string>& argv,
                         const std::filesystem::path& work_dir,
                         const std::vector<std::string>& environment = {});

// The path of the running executable (/proc/self/exe).
std::filesystem::path currentExecutable();

}  // namespace gib
