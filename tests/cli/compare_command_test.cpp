// `gibench compare` as a user runs it: the table, the JSON object, the maps, and bad input.
#include "image/exr_io.h"
#include "support/run_command.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <limits>

namespace gib::test {
namespace {

namespace fs = std::filesystem;

void writeImage(const fs::path& path, int width, int height, float value, float nan_at = -1) {
  image::Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) image.pixel(x, y)[c] = value + 0.01f * float((x + y) % 7);
  if (nan_at >= 0) image.pixel(int(nan_at), 0)[1] = std::numeric_limits<float>::quiet_NaN();
  image::writeExr(path, {{"", image}}, {{"gibench/test", "1"}});
}

TEST(CompareCommand, PrintsOneJsonObjectWithEveryMetric) {
  TempDir dir;
  writeImage(dir / "ref.exr", 48, 32, 0.5f);
  writeImage(dir / "test.exr", 48, 32, 0.55f, 3);
  CommandResult r = runGibench(
      {"compare", (dir / "ref.exr").string(), (dir / "test.exr").string(), "--json"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["nonfinite"], 1);
  for (const char* key : {"mse", "rmse", "mae", "relmse", "mape", "smape", "psnr", "block_bias",
                          "ssim", "flip_mean", "flip_median", "flip_q1", "flip_q3", "hdrflip_mean"})
    EXPECT_TRUE(j["metrics"].contains(key)) << key;
  // The offset is 0.05 on every finite pixel.
  EXPECT_NEAR(j["metrics"]["mae"].get<double>(), 0.05, 1e-5);
}

TEST(CompareCommand, SelectedMetricsAndMapsAsExrAndPng) {
  TempDir dir;
  writeImage(dir / "ref.exr", 40, 30, 0.5f);
  writeImage(dir / "test.exr", 40, 30, 0.6f);
  CommandResult r = runGibench({"compare", (dir / "ref.exr").string(), (dir / "test.exr").string(),
                                "--metrics", "relmse,flip", "--maps", (dir / "maps").string()},
                               dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("relmse"), std::string::npos);
  EXPECT_NE(r.out.find("flip_mean"), std::string::npos);
  EXPECT_EQ(r.out.find("ssim"), std::string::npos);
  for (const char* name : {"relmse.exr", "relmse.png", "flip.exr", "flip.png"})
    EXPECT_TRUE(fs::exists(dir / "maps" / name)) << name;
  image::ExrFile map = image::readExr(dir / "maps" / "relmse.exr");
  ASSERT_EQ(map.layers.size(), 1u);
  EXPECT_EQ(map.layers[0].image.channels(), 1);
}

TEST(CompareCommand, ReadsTheRgbOfRgbaFiles) {
  // Blender writes RGBA; alpha (here 0.25, not 1) must not enter any figure.
  TempDir dir;
  image::Image rgb(24, 16), rgba(24, 16, 4);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 24; ++x)
      for (int c = 0; c < 4; ++c) {
        const float value = 0.1f * float(c + 1) + 0.01f * float(x + 3 * y);
        if (c < 3) rgb.pixel(x, y)[c] = value;
        rgba.pixel(x, y)[c] = c < 3 ? value : 0.25f;
      }
  image::writeExr(dir / "rgb.exr", {{"", rgb}}, {});
  image::writeExr(dir / "rgba.exr", {{"", rgba}}, {});
  CommandResult r = runGibench({"compare", (dir / "rgb.exr").string(), (dir / "rgba.exr").string(),
                                "--metrics", "mae", "--json"},
                               dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["metrics"]["mae"].get<double>(), 0.0);
  EXPECT_EQ(j["means"]["test"], j["means"]["reference"]);
  // Mean of R: 0.1 + 0.01·(mean of x + 3y) = 0.1 + 0.01·(11.5 + 22.5).
  EXPECT_NEAR(j["means"]["test"][0].get<double>(), 0.44, 1e-6);
}

TEST(CompareCommand, EveryChannelOfRgbIsRequired) {
  TempDir dir;
  writeImage(dir / "ref.exr", 4, 3, 0.5f);
  // An EXR of R, G and A only, made by another writer (ours always writes R, G and B).
  CommandResult made =
      runProgram({"oiiotool", "--pattern", "constant:color=0.1,0.2,0.3", "4x3", "3", "--chnames",
                  "R,G,A", "-d", "float", "-o", (dir / "no_blue.exr").string()},
                 dir.path());
  ASSERT_EQ(made.exit_code, 0) << made.err;
  CommandResult r = runGibench(
      {"compare", (dir / "ref.exr").string(), (dir / "no_blue.exr").string()}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(countLines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("no B channel"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST(CompareCommand, BadInputExitsWithCodeTwoAndOneLine) {
  TempDir dir;
  writeImage(dir / "ref.exr", 40, 30, 0.5f);
  writeImage(dir / "small.exr", 20, 30, 0.5f);
  writeImage(dir / "nan.exr", 40, 30, 0.5f, 2);
  const std::string ref = (dir / "ref.exr").string();
  struct Case {
    std::vector<std::string> args;
    std::string message_part;
  };
  const std::vector<Case> cases = {
      {{"compare", ref, (dir / "small.exr").string()}, "same --width"},
      {{"compare", ref, (dir / "missing.exr").string()}, "missing.exr"},
      {{"compare", ref, ref, "--metrics", "flip,psnrr"}, "psnrr"},
      {{"compare", (dir / "nan.exr").string(), ref}, "NaN"},
      {{"compare", ref, ref, "--ppd", "0"}, "--ppd"},
  };
  for (const Case& c : cases) {
    CommandResult r = runGibench(c.args, dir.path());
    EXPECT_EQ(r.exit_code, 2) << c.message_part << ": " << r.err;
    EXPECT_EQ(countLines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(c.message_part), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

}  // namespace
}  // namespace gib::test
