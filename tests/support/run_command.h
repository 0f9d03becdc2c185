// Runs the gibench binary as a user would, capturing exit code, stdout and stderr.
#pragma once

#include "common/subprocess.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gib::test {

// What a program printed and how it ended (common/subprocess.h).
using CommandResult = ProgramResult;
using gib::runProgram;

// runProgram of the gibench binary. The command runs with GIBENCH_GL_DEBUG=1 (a GL error fails
// it) and `environment` added.
CommandResult runGibench(const std::vector<std::string>& args,
                         const std::filesystem::path& work_dir,
                         const std::vector<std::string>& environment = {});

// Number of lines in `text` (a final line without '\n' counts).
int countLines(const std::string& text);

}  // namespace gib::test
