// `gibench raycast-bench` as a user runs it: every structure's row for every kind of rays, each
// with its mismatches against Embree, rays per second, build time and memory, in raycast.json, the
// CSV and a well-formed page with its chart, all recording what produced them; a structure over
// the brute-force limit is skipped, and says so.
#include "support/markup_check.h"
#include "support/read_text.h"
#include "support/run_command.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

namespace gib::test {
namespace {

namespace fs = std::filesystem;

TEST(RaycastBenchCommand, WritesEveryStructuresRowForEveryKindOfRays) {
  TempDir dir;
  const fs::path out = dir / "bench";
  const CommandResult r = runGibench(
      {"raycast-bench", "--scene", "cornell", "--sweep", "blocks=false,true", "--out", out.string(),
       "--width", "24", "--height", "16", "--repeats", "1", "--brute-force-limit", "5000"},
      dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(readText(out / "raycast.json"));
  EXPECT_FALSE(j["gibench_version"].get<std::string>().empty());
  EXPECT_FALSE(j["embree_version"].get<std::string>().empty());
  EXPECT_EQ(j["parameters"]["width"], 24);
  // Two scenes (the empty box: 10 triangles to 32 with the blocks), three kinds of rays.
  ASSERT_EQ(j["cases"].size(), 6u);
  EXPECT_LT(j["cases"][0]["triangles"].get<int>(), j["cases"][3]["triangles"].get<int>());
  for (const auto& c : j["cases"]) {
    EXPECT_EQ(c["scene_hash"].get<std::string>().size(), 32u);
    EXPECT_GT(c["ray_count"].get<int>(), 0);
    ASSERT_EQ(c["structures"].size(), 6u);
    EXPECT_EQ(c["structures"][0]["name"], "embree");
    for (const auto& s : c["structures"]) {
      if (s.contains("skipped")) {
        // 24 × 16 rays against ≥ 10 triangles is over the limit of 5 000 tests.
        EXPECT_TRUE(s["name"] == "brute_force" || s["name"] == "ray_engine" ||
                    s["name"] == "ray_engine_cones")
            << s.dump();
        continue;
      }
      EXPECT_GT(s["mrays_per_second"].get<double>(), 0.0) << s.dump();
      EXPECT_GT(s["bytes"].get<double>(), 0.0) << s.dump();
      EXPECT_GE(s["build_ms"].get<double>(), 0.0);
      if (s["name"] != "embree") {
        // The Cornell box's walls: nothing the IVM test gets wrong.
        EXPECT_EQ(s["mismatches"], 0) << s.dump();
      }
    }
  }
  const std::string csv = readText(out / "raycast.csv");
  EXPECT_EQ(countLines(csv), 1 + 6 * 6);
  const std::string page = readText(out / "index.html");
  EXPECT_EQ(markupProblem(page), "");
  EXPECT_NE(page.find("loose_kd_tree"), std::string::npos);
  EXPECT_NE(page.find("<svg"), std::string::npos);  // the rays/s chart
  EXPECT_NE(page.find("skipped"), std::string::npos);
}

}  // namespace
}  // namespace gib::test
