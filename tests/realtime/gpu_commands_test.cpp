// The profiler's GPU-command counts are complete only if every draw and dispatch of the realtime
// layer goes through realtime/gl/gpu_commands.h: a raw glDraw* or glDispatch* anywhere else would
// make a frame look cheaper in commands than it is.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace gib {
namespace {

namespace fs = std::filesystem;

TEST(GpuCommands, EveryDrawAndDispatchOfTheRealtimeLayerIsCounted) {
  const fs::path root = fs::path(GIB_SOURCE_DIR) / "realtime";
  const fs::path wrapper = root / "gl" / "gpu_commands.cpp";
  const std::regex raw(R"(\bgl(Draw\w*|MultiDraw\w*|DispatchCompute\w*)\s*\()");
  std::vector<std::string> bypasses;
  int files = 0, wrapped = 0;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(root)) {
    const std::string extension = entry.path().extension().string();
    if (extension != ".cpp" && extension != ".h") continue;
    ++files;
    std::ifstream in(entry.path());
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      if (!std::regex_search(line, raw)) continue;
      if (entry.path() == wrapper)
        ++wrapped;
      else
        bypasses.push_back(entry.path().string() + ":" + std::to_string(number) + ": " + line);
    }
  }
  EXPECT_GT(files, 50) << "the realtime sources were not found under " << root;
  EXPECT_GE(wrapped, 3) << "the pattern no longer finds the wrapper's own GL calls";
  std::ostringstream list;
  for (const std::string& b : bypasses) list << b << "\n";
  EXPECT_TRUE(bypasses.empty()) << "draw through gl::drawArrays / gl::dispatchCompute:\n"
                                << list.str();
}

}  // namespace
}  // namespace gib
