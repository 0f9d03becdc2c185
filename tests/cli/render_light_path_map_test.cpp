// `gibench render --technique light_path_map` as a user runs it: the image with its path class,
// the auxiliary images of Figs. 8.12/8.13, the preprocessing statistics; counts that do not fit
// each other refused with one line and exit code 2, before anything is written.
#include "image/exr_io.h"
#include "support/run_command.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace gib::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> renderArguments(const TempDir& dir, std::vector<std::string> sets) {
  std::vector<std::string> arguments = {
      "render",  "--scene",  "cornell",  "--technique", "light_path_map",
      "--width", "32",       "--height", "24",          "--frames",
      "1",       "--warmup", "0",        "--out",       (dir / "lpm.exr").string()};
  for (std::string& set : sets) {
    arguments.push_back("--set");
    arguments.push_back(std::move(set));
  }
  return arguments;
}

TEST(RenderLightPathMap, WritesTheImageItsFiguresAndThePreprocessingBreakdown) {
  TempDir dir;
  CommandResult r =
      runGibench(renderArguments(dir, {"entry_points=64", "clusters=8", "panes_used=4", "atlas=64",
                                       "vpl_shadow_map_size=32", "light_samples=2"}),
                 dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const image::ExrFile exr = image::readExr(dir / "lpm.exr");
  EXPECT_EQ(exr.metadata.at("gibench/technique"), "light_path_map");
  EXPECT_EQ(exr.metadata.at("gibench/path_class"), "L(D|S|P)*E");
  for (const char* aux :
       {"lpm-indirect.png", "lpm-entry-points.png", "lpm-atlas.png", "lpm-local-and-lpm.png"})
    EXPECT_TRUE(fs::exists(dir / aux)) << aux << "\n" << r.out;
  for (const char* statistic : {"prepare_ray_caster_ms", "prepare_light_tracing_ms",
                                "prepare_lpm_ms", "virtual_lights", "pane_memory_mb"})
    EXPECT_NE(r.out.find(statistic), std::string::npos) << statistic << "\n" << r.out;
  for (const char* pass : {"entry irradiance", "pane selection", "indirect atlas"})
    EXPECT_NE(r.out.find(pass), std::string::npos) << pass << "\n" << r.out;
}

TEST(RenderLightPathMap, CountsThatDoNotFitExitTwoWithOneLineAndNoOutput) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"entry_points=0"}, "entry_points"},
      {{"entry_points=16", "clusters=32"}, "give at most one cluster per entry point"},
      {{"clusters=8", "panes_used=9"}, "give at most the cluster count"},
  };
  for (const auto& [sets, fix] : cases) {
    TempDir dir;
    CommandResult r = runGibench(renderArguments(dir, sets), dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(countLines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(fix), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "lpm.exr"));
  }
}

}  // namespace
}  // namespace gib::test
