// results.csv as a spreadsheet or a script reads it: RFC 4180 quoting, one row per job, one
// column per metric value of any job.
#include "results/results_csv.h"

#include "support/synthetic_results.h"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>

namespace gib::results {
namespace {

using ::testing::ElementsAre;

// A strict RFC 4180 reader (quoted fields may hold commas, doubled quotes and line breaks), so
// that the test checks what a spreadsheet would read rather than the text.
std::vector<std::vector<std::string>> parseCsv(const std::string& text) {
  std::vector<std::vector<std::string>> rows(1, std::vector<std::string>(1));
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    std::string& field = rows.back().back();
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      rows.back().emplace_back();
    } else if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') {
      ++i;
      rows.emplace_back(1);
    } else {
      field += c;
    }
  }
  EXPECT_FALSE(quoted) << "unterminated quoted field";
  EXPECT_EQ(rows.back(), std::vector<std::string>(1)) << "no line end after the last row";
  rows.pop_back();
  return rows;
}

// Row `row`'s cells by header name.
std::map<std::string, std::string> cellsOf(const std::vector<std::vector<std::string>>& rows,
                                           std::size_t row) {
  std::map<std::string, std::string> cells;
  for (std::size_t i = 0; i < rows[0].size(); ++i) cells[rows[0][i]] = rows[row].at(i);
  return cells;
}

TEST(ResultsCsv, OneRowPerJobWithEveryColumn) {
  const RunResults results = test::richResults();
  const auto rows = parseCsv(resultsCsv(results));
  ASSERT_EQ(rows.size(), 1 + results.jobs.size());
  for (const auto& row : rows) EXPECT_EQ(row.size(), rows[0].size());
  EXPECT_THAT(rows[0],
              ElementsAre("run_id", "git_commit", "job", "case", "scene", "technique", "parameters",
                          "scene_parameters", "width", "height", "path_class", "reference_key",
                          "spp", "relmse", "flip_mean", "psnr", "full_relmse", "full_ssim",
                          "frame_median_ms", "upload_ms", "prepare_ms", "seconds"));
  const auto technique = cellsOf(rows, 1);
  EXPECT_EQ(technique.at("run_id"), results.run.id);
  EXPECT_EQ(technique.at("job"), "cornell-direct/shadow=pcf");
  EXPECT_EQ(technique.at("parameters"), "shadow=pcf;light_samples=16");
  EXPECT_EQ(technique.at("relmse"), "0.0123");
  EXPECT_EQ(technique.at("psnr"), "inf");
  EXPECT_EQ(technique.at("full_ssim"), "0.91");
  EXPECT_EQ(technique.at("spp"), "256");
  EXPECT_EQ(technique.at("frame_median_ms"), fmt::format("{}", *results.jobs[0].frameMedianMs()));
  EXPECT_EQ(technique.at("prepare_ms"), "11");
  // The reference job has neither flip_mean nor full-reference values nor timings.
  const auto reference = cellsOf(rows, 2);
  EXPECT_EQ(reference.at("relmse"), "-inf");
  EXPECT_EQ(reference.at("flip_mean"), "");
  EXPECT_EQ(reference.at("full_relmse"), "");
  EXPECT_EQ(reference.at("frame_median_ms"), "");
}

TEST(ResultsCsv, QuotesCommasQuotesAndLineBreaks) {
  RunResults results = test::richResults();
  results.jobs[0].case_name = "two\nlines";
  results.jobs[1].path_class = "a,b";
  const std::string text = resultsCsv(results);
  EXPECT_NE(text.find("\"light_scale=1.5;name=with \"\"quotes\"\", commas\""), std::string::npos);
  EXPECT_NE(text.find("\"two\nlines\""), std::string::npos);
  const auto rows = parseCsv(text);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(cellsOf(rows, 1).at("scene_parameters"),
            "light_scale=1.5;name=with \"quotes\", commas");
  EXPECT_EQ(cellsOf(rows, 1).at("case"), "two\nlines");
  EXPECT_EQ(cellsOf(rows, 2).at("path_class"), "a,b");
  // Unquoted fields stay bare.
  EXPECT_NE(text.find(",cornell,direct,"), std::string::npos);
}

TEST(ResultsCsv, MetricColumnsAreTheUnionInFirstSeenOrder) {
  const RunResults results =
      test::syntheticRun("run", {test::syntheticJob("a", {{"relmse", 1}, {"ssim", 0.5}}),
                                 test::syntheticJob("b", {{"flip_mean", 2}, {"relmse", 3}})});
  const auto rows = parseCsv(resultsCsv(results));
  ASSERT_EQ(rows.size(), 3u);
  const std::vector<std::string> metrics(rows[0].begin() + 13, rows[0].end() - 4);
  EXPECT_THAT(metrics, ElementsAre("relmse", "ssim", "flip_mean"));
  EXPECT_EQ(cellsOf(rows, 2).at("ssim"), "");
  EXPECT_EQ(cellsOf(rows, 2).at("relmse"), "3");
  EXPECT_EQ(cellsOf(rows, 1).at("flip_mean"), "");
}

TEST(ResultsCsv, RunWithoutJobsIsTheHeaderOnly) {
  const auto rows = parseCsv(resultsCsv(test::syntheticRun("run", {})));
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].back(), "seconds");
}

}  // namespace
}  // namespace gib::results
