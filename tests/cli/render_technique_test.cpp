// `gibench render --technique direct` and `gibench list techniques` as a user runs them: the
// image, its metadata (technique, parameters, GL identity, path class), the pass timing table
// and JSON.
#include "image/exr_io.h"
#include "support/run_command.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace gib::test {
namespace {

namespace fs = std::filesystem;

TEST(RenderTechnique, DirectWritesExrPngTimingsAndTable) {
  TempDir dir;
  CommandResult r = runGibench({"render",
                                "--scene",
                                "cornell",
                                "--technique",
                                "direct",
                                "--set",
                                "shadow=pcf",
                                "--set",
                                "light_samples=4",
                                "--width",
                                "40",
                                "--height",
                                "30",
                                "--warmup",
                                "1",
                                "--frames",
                                "3",
                                "--timings-json",
                                (dir / "t.json").string(),
                                "--out",
                                (dir / "direct.exr").string()},
                               dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "direct.png"));
  image::ExrFile exr = image::readExr(dir / "direct.exr");
  EXPECT_EQ(exr.rgb().width(), 40);
  EXPECT_EQ(exr.rgb().height(), 30);
  EXPECT_EQ(exr.metadata["gibench/technique"], "direct");
  EXPECT_NE(exr.metadata["gibench/parameters"].find("\"shadow\":\"pcf\""), std::string::npos)
      << exr.metadata["gibench/parameters"];
  EXPECT_EQ(exr.metadata["gibench/path_class"], "L(D|S|P){0,1}E");
  EXPECT_EQ(exr.metadata["gibench/max_bounces"], "1");
  EXPECT_EQ(exr.metadata["gibench/frames"], "3");
  for (const char* key : {"gibench/version", "gibench/scene_hash", "gibench/gl_renderer",
                          "gibench/gl_vendor", "gibench/gl_version", "gibench/gl_device",
                          "gibench/timing_clock", "gibench/frame_ms_median"})
    EXPECT_FALSE(exr.metadata[key].empty()) << key;
  // The light is seen directly and lights the room: the image is not black.
  double sum = 0;
  for (float v : exr.rgb().data()) sum += v;
  EXPECT_GT(sum, 0.0);
  // The table names the passes; the JSON has the same passes with per-frame samples.
  for (const char* pass : {"frame", "g-buffer", "shadow map", "shading"})
    EXPECT_NE(r.out.find(pass), std::string::npos) << pass << "\n" << r.out;
  nlohmann::json timings = nlohmann::json::parse(std::ifstream(dir / "t.json"));
  ASSERT_TRUE(timings.contains("passes"));
  bool found_shadow = false;
  for (const auto& pass : timings["passes"])
    if (pass["name"] == "shadow map") found_shadow = true;
  EXPECT_TRUE(found_shadow) << timings.dump(1);
}

TEST(RenderTechnique, NoEglDriverIsOneLineNamingTheMesaPackageAndExitCodeTwo) {
  TempDir dir;
  // GLVND finds no vendor library: what a machine without Mesa's EGL looks like.
  CommandResult r = runGibench({"render", "--scene", "cornell", "--technique", "direct", "--out",
                                (dir / "direct.exr").string()},
                               dir.path(), {"__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(countLines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("libegl-mesa0"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "direct.exr"));
}

TEST(RenderTechnique, GlDeviceChoiceIsRecorded) {
  TempDir dir;
  CommandResult r =
      runGibench({"render", "--scene", "cornell", "--technique", "direct", "--width", "16",
                  "--height", "16", "--frames", "1", "--warmup", "0", "--gl-device", "surfaceless",
                  "--out", (dir / "direct.exr").string()},
                 dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(image::readExr(dir / "direct.exr").metadata["gibench/gl_device"], "surfaceless");
}

TEST(ListCommand, ListsTechniquesWithTheirParameters) {
  TempDir dir;
  CommandResult r = runGibench({"list", "techniques"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* part : {"reference", "direct", "shadow", "light_samples", "shadow_map_size",
                           "path class (defaults): L(D|S|P){0,1}E"})
    EXPECT_NE(r.out.find(part), std::string::npos) << part << "\n" << r.out;
}

}  // namespace
}  // namespace gib::test
