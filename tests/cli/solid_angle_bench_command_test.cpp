// `gibench solid-angle-bench` as a user runs it: the statistics, the per-point errors, the Fig. 8
// panels and a well-formed page, all recording what produced them.
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

TEST(SolidAngleBenchCommand, WritesTheStatisticsErrorsPanelsAndPage) {
  TempDir dir;
  const fs::path out = dir / "bench";
  const CommandResult r =
      runGibench({"solid-angle-bench", "--out", out.string(), "--grid", "6", "--timing-samples",
                  "50", "--sizes", "16", "--figure-size", "16", "--schemes", "regular,jittered4"},
                 dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(readText(out / "solid_angle_bench.json"));
  EXPECT_FALSE(j["gibench_version"].get<std::string>().empty());
  EXPECT_EQ(j["parameters"]["points"], 36);
  EXPECT_EQ(j["parameters"]["timing_samples"], 50);
  ASSERT_EQ(j["results"].size(), 2u);
  for (const auto& row : j["results"]) {
    EXPECT_EQ(row["size"], 16);
    EXPECT_EQ(row["timing_samples"], 50);
    EXPECT_GT(row["render"]["median_ms"].get<double>(), 0);
    EXPECT_GE(row["max_abs_error_sr"].get<double>(), row["mean_abs_error_sr"].get<double>());
  }
  // One line per point and a header, one error column per scheme and size.
  const std::string csv = readText(out / "solid_angle_errors.csv");
  EXPECT_EQ(countLines(csv), 37);
  EXPECT_NE(csv.find("x,z,regular_16_error_sr,jittered4_16_error_sr"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "error_regular_16.png"));
  EXPECT_TRUE(fs::exists(out / "error_jittered4_16.png"));
  EXPECT_FALSE(fs::exists(out / "error_jittered1_16.png"));  // not asked for
  const std::string page = readText(out / "index.html");
  EXPECT_EQ(markupProblem(page), "");
  EXPECT_EQ(countOccurrences(page, "<img src=\"error_"), 2);
  EXPECT_NE(page.find("Fig. 9"), std::string::npos);
}

}  // namespace
}  // namespace gib::test
