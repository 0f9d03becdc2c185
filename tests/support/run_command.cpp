#include "support/run_command.h"

#include <stdexcept>

namespace gib::test {

CommandResult runGibench(const std::vector<std::string>& args,
                         const std::filesystem::path& work_dir,
                         const std::vector<std::string>& environment) {
#ifndef GIB_GIBENCH_PATH
  throw std::runtime_error("tests were built without the gibench binary");
#else
  std::vector<std::string> argv = {GIB_GIBENCH_PATH};
  argv.insert(argv.end(), args.begin(), args.end());
  // GL debug output on: a GL error in any command fails it (exit 3), hence the test.
  std::vector<std::string> env = environment;
  env.push_back("GIBENCH_GL_DEBUG=1");
  return runProgram(argv, work_dir, env);
#endif
}

int countLines(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n';
  if (!text.empty() && text.back() != '\n') ++lines;
  return lines;
}

}  // namespace gib::test
