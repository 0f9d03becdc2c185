// `gibench render --technique stochastic_radiosity` as a user runs it: iterations from the
// command line, and bad parameters refused with one line and exit code 2, writing nothing.
#include "support/run_command.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace gib::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> renderArguments(const TempDir& dir, const std::string& set) {
  return {"render",
          "--scene",
          "cornell",
          "--technique",
          "stochastic_radiosity",
          "--set",
          set,
          "--iterations",
          "4",
          "--width",
          "16",
          "--height",
          "16",
          "--warmup",
          "0",
          "--frames",
          "1",
          "--out",
          (dir / "out.exr").string()};
}

TEST(RenderStochasticRadiosity, RendersWithIterations) {
  TempDir dir;
  const CommandResult r = runGibench(renderArguments(dir, "atlas=64"), dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "out.exr"));
}

TEST(RenderStochasticRadiosity, BadParametersExitWithCodeTwoAndOneLine) {
  for (const char* set : {"atlas=100", "selection=both", "projection=fisheye", "tessellation=9",
                          "hemicube=8", "seed=-1", "iterations=5"}) {
    TempDir dir;
    const CommandResult r = runGibench(renderArguments(dir, set), dir.path());
    EXPECT_EQ(r.exit_code, 2) << set << ": " << r.err;
    EXPECT_EQ(countLines(r.err), 1) << set << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.exr")) << set;
  }
}

}  // namespace
}  // namespace gib::test
