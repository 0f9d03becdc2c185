// `gibench render` as a user runs it: outputs, metadata, determinism across --threads, and one
// clear line with exit code 2 (and no output file) for every kind of bad input.
#include "image/exr_io.h"
#include "reference/reference_output.h"
#include "support/run_command.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

namespace gib::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> renderArgs(const fs::path& out, std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"render", "--scene",  "cornell",   "--width",
                                   "24",     "--height", "16",        "--spp",
                                   "4",      "--out",    out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

TEST(RenderCommand, WritesExrWithLayersAndMetadataAndPng) {
  TempDir dir;
  CommandResult r = runGibench(renderArgs(dir / "cornell.exr", {"--checkpoints"}), dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "cornell.png"));
  EXPECT_NE(r.out.find("cornell.exr"), std::string::npos);
  EXPECT_NE(r.out.find("cornell.png"), std::string::npos);
  image::ExrFile exr = image::readExr(dir / "cornell.exr");
  EXPECT_EQ(exr.rgb().width(), 24);
  EXPECT_EQ(exr.rgb().height(), 16);
  for (const char* layer : {"variance", "direct", "indirect"})
    EXPECT_NE(exr.findLayer(layer), nullptr) << layer;
  for (const char* key : {"gibench/version", "gibench/scene_hash", "gibench/spp", "gibench/seed",
                          "gibench/min_bounces", "gibench/max_bounces", "gibench/render_seconds",
                          "gibench/rays_per_second", "gibench/technique"})
    EXPECT_TRUE(exr.metadata.count(key)) << key;
  EXPECT_EQ(exr.metadata["gibench/spp"], "4");
  // Four samples: four replicas of one, whose spread is the variance (3 degrees of freedom).
  EXPECT_EQ(exr.metadata["gibench/sampler"], "sobol");
  EXPECT_EQ(exr.metadata["gibench/replicas"], "4");
  EXPECT_NE(r.out.find("from 4 replicas of 1 spp (3 degrees of freedom)"), std::string::npos);
  EXPECT_EQ(exr.metadata["gibench/scene"], "cornell");
  // Checkpoints at 1, 2 and 4 spp.
  for (const char* name : {"cornell.spp0001.exr", "cornell.spp0002.exr", "cornell.spp0004.exr"})
    EXPECT_TRUE(fs::exists(dir / name)) << name;
}

TEST(RenderCommand, PixelsAreBitIdenticalWithOneOrTwoThreads) {
  TempDir dir;
  ASSERT_EQ(runGibench(renderArgs(dir / "a.exr", {"--threads", "1"}), dir.path()).exit_code, 0);
  ASSERT_EQ(runGibench(renderArgs(dir / "b.exr", {"--threads", "2"}), dir.path()).exit_code, 0);
  image::ExrFile a = image::readExr(dir / "a.exr");
  image::ExrFile b = image::readExr(dir / "b.exr");
  ASSERT_EQ(a.layers.size(), b.layers.size());
  for (const image::Layer& layer : a.layers) {
    const image::Image* other = b.findLayer(layer.name);
    ASSERT_NE(other, nullptr);
    ASSERT_TRUE(layer.image.sameSize(*other));
    EXPECT_EQ(std::memcmp(layer.image.data().data(), other->data().data(),
                          layer.image.data().size_bytes()),
              0)
        << "layer '" << layer.name << "'";
  }
  // Everything but the run-dependent keys (timing, memory) is identical too.
  for (const char* key : ref::kRunDependentKeys) {
    EXPECT_TRUE(a.metadata.count(key)) << key;
    a.metadata.erase(key);
    b.metadata.erase(key);
  }
  EXPECT_EQ(a.metadata, b.metadata);
}

// --obscurance renders W(x) instead of radiance, and the image says so.
TEST(RenderCommand, WritesAnObscuranceWithItsMetadata) {
  TempDir dir;
  CommandResult r =
      runGibench(renderArgs(dir / "w.exr", {"--obscurance", "ambient_occlusion",
                                            "--obscurance-mode", "spectral", "--d-max", "0.1"}),
                 dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("obscurance(ambient_occlusion, spectral, d_max=0.1)"), std::string::npos)
      << r.out;
  image::ExrFile exr = image::readExr(dir / "w.exr");
  EXPECT_EQ(exr.metadata["gibench/obscurance"],
            "obscurance(ambient_occlusion, spectral, d_max=0.1)");
  EXPECT_EQ(exr.metadata["gibench/light_paths"], "none");
  ASSERT_NE(exr.findLayer("variance"), nullptr);
  // W lies in [0, 1] (spectral: up to the largest albedo), unlike the light's radiance.
  const image::Image mean = exr.rgb();
  for (float v : mean.data()) ASSERT_TRUE(v >= 0.0f && v <= 1.0f) << v;
  // A radiance render carries no such key.
  ASSERT_EQ(runGibench(renderArgs(dir / "l.exr"), dir.path()).exit_code, 0);
  EXPECT_EQ(image::readExr(dir / "l.exr").metadata.count("gibench/obscurance"), 0u);
}

// A path expression's class is recorded as given, in place of the bounce range it replaces.
TEST(RenderCommand, RecordsThePathExpressionInTheMetadata) {
  TempDir dir;
  CommandResult r = runGibench(renderArgs(dir / "c.exr", {"--paths", "L S+ D E"}), dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  image::ExrFile exr = image::readExr(dir / "c.exr");
  EXPECT_EQ(exr.metadata["gibench/paths"], "LS+DE");
  EXPECT_EQ(exr.metadata["gibench/path_class"], "LS+DE");
  EXPECT_FALSE(exr.metadata.count("gibench/min_bounces"));
  EXPECT_FALSE(exr.metadata.count("gibench/max_bounces"));
  // The bounce options are the shorthand: their class is written in the same notation.
  r = runGibench(renderArgs(dir / "b.exr", {"--min-bounces", "1", "--max-bounces", "2"}),
                 dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  exr = image::readExr(dir / "b.exr");
  EXPECT_EQ(exr.metadata["gibench/path_class"], "L(D|S|P){1,2}E");
  EXPECT_FALSE(exr.metadata.count("gibench/paths"));
}

struct BadInput {
  std::string name;
  std::vector<std::string> args;  // "OUT" is replaced by the output path
  std::string message_part;
};

// Test names and failure messages show the case's name, not its bytes.
void PrintTo(const BadInput& input, std::ostream* os) {
  *os << input.name;
}

class RenderBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(RenderBadInput, ExitsWithCodeTwoAndOneLineAndNoOutput) {
  TempDir dir;
  std::vector<std::string> args = GetParam().args;
  for (std::string& a : args)
    if (a == "OUT") a = (dir / "out.exr").string();
  if (GetParam().name == "malformed_scene_file") {
    std::ofstream(dir / "broken.toml") << "[camera\nposition = [0, 0, 0]\n";
    for (std::string& a : args)
      if (a == "broken.toml") a = (dir / "broken.toml").string();
  }
  CommandResult r = runGibench(args, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(countLines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(GetParam().message_part), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
  EXPECT_FALSE(fs::exists(dir / "out.png"));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, RenderBadInput,
    ::testing::Values(
        BadInput{"unknown_scene", {"render", "--scene", "cornel", "--out", "OUT"}, "cornel"},
        BadInput{
            "zero_spp", {"render", "--scene", "cornell", "--spp", "0", "--out", "OUT"}, "--spp"},
        BadInput{"missing_scene_file",
                 {"render", "--scene", "/nonexistent/room.toml", "--out", "OUT"},
                 "room.toml"},
        BadInput{"malformed_scene_file",
                 {"render", "--scene", "broken.toml", "--out", "OUT"},
                 "broken.toml:"},
        BadInput{"unwritable_output",
                 {"render", "--scene", "cornell", "--out", "/nonexistent/dir/out.exr"},
                 "/nonexistent/dir"},
        BadInput{"not_exr_output", {"render", "--scene", "cornell", "--out", "image.png"}, ".exr"},
        BadInput{"unknown_technique",
                 {"render", "--scene", "cornell", "--technique", "magic", "--out", "OUT"},
                 "magic"},
        BadInput{"technique_parameter_for_reference",
                 {"render", "--scene", "cornell", "--set", "foo=1", "--out", "OUT"},
                 "--set"},
        BadInput{"min_above_max",
                 {"render", "--scene", "cornell", "--min-bounces", "3", "--max-bounces", "1",
                  "--out", "OUT"},
                 "--min-bounces"},
        BadInput{"paths_syntax_error",
                 {"render", "--scene", "cornell", "--paths", "L(D", "--out", "OUT"},
                 "path expression 'L(D': column 2: '(' is not closed"},
        BadInput{"paths_matching_no_light_path",
                 {"render", "--scene", "cornell", "--paths", "DE", "--out", "OUT"},
                 "matches no light path"},
        BadInput{"paths_with_bounces",
                 {"render", "--scene", "cornell", "--paths", "LDE", "--max-bounces", "1", "--out",
                  "OUT"},
                 "--paths and --max-bounces both choose the path class"},
        BadInput{"paths_for_technique",
                 {"render", "--scene", "cornell", "--technique", "direct", "--paths", "LDE",
                  "--out", "OUT"},
                 "--paths applies to the reference path tracer"},
        BadInput{"replicas_not_dividing_spp",
                 {"render", "--scene", "cornell", "--spp", "8", "--replicas", "3", "--out", "OUT"},
                 "--replicas 3 does not divide --spp 8"},
        BadInput{"replicas_above_spp",
                 {"render", "--scene", "cornell", "--spp", "8", "--replicas", "16", "--out", "OUT"},
                 "--replicas"},
        BadInput{"unknown_sampler",
                 {"render", "--scene", "cornell", "--sampler", "halton", "--out", "OUT"},
                 "halton"},
        BadInput{"non_numeric_spp",
                 {"render", "--scene", "cornell", "--spp", "many", "--out", "OUT"},
                 "spp"},
        BadInput{"missing_out", {"render", "--scene", "cornell"}, "--out"},
        BadInput{"technique_unknown_parameter",
                 {"render", "--scene", "cornell", "--technique", "direct", "--set", "foo=1",
                  "--out", "OUT"},
                 "foo"},
        BadInput{"technique_parameter_out_of_range",
                 {"render", "--scene", "cornell", "--technique", "direct", "--set",
                  "shadow_map_size=8", "--out", "OUT"},
                 "shadow_map_size"},
        BadInput{"irradiance_volume_grid_too_small",
                 {"render", "--scene", "cornell", "--technique", "irradiance_volume", "--set",
                  "grid=1", "--out", "OUT"},
                 "grid"},
        BadInput{"irradiance_volume_atlas_too_large",
                 {"render", "--scene", "cornell", "--technique", "irradiance_volume", "--set",
                  "grid=16", "--set", "face=64", "--out", "OUT"},
                 "lower grid or face"},
        BadInput{"irradiance_volume_unknown_motion",
                 {"render", "--scene", "cornell", "--technique", "irradiance_volume", "--set",
                  "motion=camera", "--out", "OUT"},
                 "camera"},
        BadInput{"technique_unknown_choice",
                 {"render", "--scene", "cornell", "--technique", "direct", "--set", "shadow=soft",
                  "--out", "OUT"},
                 "soft"},
        BadInput{
            "reference_option_for_technique",
            {"render", "--scene", "cornell", "--technique", "direct", "--spp", "4", "--out", "OUT"},
            "--spp"},
        BadInput{"technique_zero_frames",
                 {"render", "--scene", "cornell", "--technique", "direct", "--frames", "0", "--out",
                  "OUT"},
                 "--frames"},
        BadInput{"technique_missing_gl_device",
                 {"render", "--scene", "cornell", "--technique", "direct", "--gl-device", "99",
                  "--out", "OUT"},
                 "GL device 99"},
        BadInput{"technique_unwritable_timings",
                 {"render", "--scene", "cornell", "--technique", "direct", "--timings-json",
                  "/nonexistent/dir/t.json", "--out", "OUT"},
                 "/nonexistent/dir"}),
    [](const auto& info) { return info.param.name; });

TEST(ListCommand, ListsBuiltinScenes) {
  TempDir dir;
  CommandResult r = runGibench({"list", "scenes"}, dir.path());
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("cornell"), std::string::npos);
  EXPECT_NE(r.out.find("furnace"), std::string::npos);
  EXPECT_EQ(runGibench({"list", "nonsense"}, dir.path()).exit_code, 2);
}

}  // namespace
}  // namespace gib::test
