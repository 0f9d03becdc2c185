// `--summary`: the Markdown a pull-request comment shows, on synthetic runs with a regression,
// failed jobs and paper values the tests choose. Markdown is read back the way a renderer would
// see it: table rows split into cells, backslash escapes removed, image links resolved against
// the run directory.
#include "reports/markdown_summary.h"

#include "reports/html_report.h"
#include "reports/number_format.h"
#include "reports/run_comparison.h"
#include "support/synthetic_report_run.h"
#include "support/temp_dir.h"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <regex>
#include <sstream>

namespace gib::reports {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

results::RunResults previousRun() {
  results::RunResults previous =
      test::syntheticReportResults("20261121-100405-smoke-00000000", "fedcba9876543210");
  previous.run.started = "2026-11-21T10:04:05Z";
  return previous;
}

std::string summaryOf(const results::RunResults& results,
                      const std::optional<results::RunResults>& previous,
                      const fs::path& run_dir = "runs/smoke") {
  return markdownSummary(results, RunComparison(results, previous), run_dir);
}

std::string lower(std::string text) {
  for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// Markdown's backslash escapes of ASCII punctuation removed.
std::string unescaped(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\' && i + 1 < text.size() &&
        std::ispunct(static_cast<unsigned char>(text[i + 1])))
      ++i;
    out += text[i];
  }
  return out;
}

// The cells of a table row ("| a | b\|c |" → {"a", "b|c"}), split at unescaped pipes.
std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> out;
  std::string cell;
  for (std::size_t i = 1; i < row.size(); ++i) {
    if (row[i] == '\\' && i + 1 < row.size()) {
      cell += row.substr(i, 2);
      ++i;
    } else if (row[i] == '|') {
      const std::size_t first = cell.find_first_not_of(' ');
      const std::size_t last = cell.find_last_not_of(' ');
      out.push_back(
          unescaped(first == std::string::npos ? "" : cell.substr(first, last - first + 1)));
      cell.clear();
    } else {
      cell += row[i];
    }
  }
  return out;
}

// The rows of the table under `heading` (header and separator left out).
std::vector<std::vector<std::string>> table(const std::string& summary,
                                            const std::string& heading) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(summary);
  bool inside = false;
  int row = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line == heading) {
      inside = true;
      continue;
    }
    if (!inside) continue;
    if (line.rfind("|", 0) != 0) {
      if (row > 0) break;
      continue;
    }
    if (row++ >= 2) rows.push_back(cells(line));
  }
  return rows;
}

std::string percentDecoded(const std::string& path) {
  std::string out;
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (path[i] == '%' && i + 2 < path.size()) {
      out += char(std::stoi(path.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += path[i];
    }
  }
  return out;
}

// The targets of the image links, ![alt](target).
std::vector<std::string> images(const std::string& summary) {
  static const std::regex kImage(R"(!\[[^\]]*\]\(([^)]*)\))");
  std::vector<std::string> targets;
  for (auto it = std::sregex_iterator(summary.begin(), summary.end(), kImage);
       it != std::sregex_iterator(); ++it)
    targets.push_back(percentDecoded((*it)[1].str()));
  return targets;
}

TEST(MarkdownSummary, TheRegressionTableListsTheInjectedRegression) {
  const results::RunResults results = test::syntheticReportResults();
  results::RunResults previous = previousRun();
  const double before = previous.jobs[1].metrics[0].second / 2;
  previous.jobs[1].metrics[0].second = before;
  const double after = results.jobs[1].metrics[0].second;

  const std::string summary = summaryOf(results, previous);
  EXPECT_THAT(summary, HasSubstr("**1 regression** (1 job)"));
  EXPECT_THAT(summary, HasSubstr("3 jobs"));
  EXPECT_THAT(summary, HasSubstr("0 failed"));
  EXPECT_THAT(summary, HasSubstr("0 paper values out of tolerance"));
  EXPECT_THAT(lower(summary), Not(HasSubstr("no regressions")));
  const results::Tolerance& tolerance = results.tolerances.forMetric("relmse");
  const auto rows = table(summary, "### Regressions");
  ASSERT_EQ(rows.size(), 1u) << summary;
  EXPECT_EQ(rows[0], (std::vector<std::string>{
                         results.jobs[1].id, "relmse", formatNumber(before), formatNumber(after),
                         formatChange((after - before) / before),
                         fmt::format("±max({}, {}·|previous|)", formatNumber(tolerance.absolute),
                                     formatNumber(tolerance.relative))}))
      << summary;
}

TEST(MarkdownSummary, ThePicturesOfRegressedJobsAreFilesOfTheRunDirectory) {
  test::TempDir dir;
  const fs::path run_dir = dir / "run";
  const results::RunResults results = test::syntheticReportResults();
  test::writeSyntheticOutputs(run_dir, results);
  results::RunResults previous = previousRun();
  previous.jobs[1].metrics[0].second /= 2;
  previous.jobs[2].metrics[0].second /= 2;
  ReportContext context;
  context.previous = previous;
  writeHtmlReport(run_dir, results, context);

  const std::string summary = summaryOf(results, previous, run_dir);
  EXPECT_THAT(summary, HasSubstr("relative to the run directory"));
  const std::vector<std::string> targets = images(summary);
  // reference, image and difference of both regressed jobs; none of the reference job.
  ASSERT_EQ(targets.size(), 6u) << summary;
  for (const std::string& target : targets) {
    EXPECT_FALSE(fs::path(target).is_absolute()) << target;
    EXPECT_TRUE(fs::is_regular_file(run_dir / target)) << target;
  }
  for (const results::JobResult* job : {&results.jobs[1], &results.jobs[2]})
    for (const std::string* png :
         {&job->outputs.reference_png, &job->outputs.image_png, &job->outputs.difference_png})
      EXPECT_NE(std::find(targets.begin(), targets.end(), *png), targets.end()) << *png;
  // The report's index and the job pages are linked the same way.
  static const std::regex kLink(R"((^|[^!])\[[^\]]*\]\(([^)]*)\))");
  int links = 0;
  for (auto it = std::sregex_iterator(summary.begin(), summary.end(), kLink);
       it != std::sregex_iterator(); ++it, ++links)
    EXPECT_TRUE(fs::is_regular_file(run_dir / percentDecoded((*it)[2].str()))) << (*it)[2];
  EXPECT_EQ(links, 3) << summary;  // the index and two job pages
}

TEST(MarkdownSummary, AtMostSixRegressedJobsShowTheirPictures) {
  results::RunResults results = test::syntheticReportResults();
  for (int i = 0; i < 8; ++i)
    results.jobs.push_back(
        test::syntheticTechniqueJob(fmt::format("shadow=pcf,light_samples={}", 10 + i), 0.004));
  results::RunResults previous = results;
  previous.run.id = "20261121-100405-smoke-00000000";
  previous.run.started = "2026-11-21T10:04:05Z";
  for (std::size_t i = 3; i < previous.jobs.size(); ++i) previous.jobs[i].metrics[0].second = 0.002;
  const std::string summary = summaryOf(results, previous);
  EXPECT_EQ(images(summary).size(), 3 * kSummaryPictureJobs) << summary;
  EXPECT_THAT(summary, HasSubstr("2 more regressed jobs"));
  EXPECT_EQ(table(summary, "### Regressions").size(), 8u);
}

TEST(MarkdownSummary, NothingToReportSaysNoRegressions) {
  const results::RunResults results = test::syntheticReportResults();
  for (const std::optional<results::RunResults>& previous :
       {std::optional<results::RunResults>(previousRun()), std::optional<results::RunResults>()}) {
    const std::string summary = summaryOf(results, previous);
    EXPECT_THAT(lower(summary), HasSubstr("no regressions"));
    EXPECT_THAT(summary, Not(HasSubstr("### ")));  // no section: nothing to list
    EXPECT_TRUE(images(summary).empty());
    EXPECT_THAT(summary, HasSubstr("[index.html](index.html)"));
  }
}

TEST(MarkdownSummary, FailedJobsMissingJobsAndPaperValuesOutOfToleranceAreListed) {
  results::RunResults results = test::syntheticReportResults();
  results::JobResult& failed = results.jobs[2];
  test::markFailed(failed, "the GL context could not be created | <no device>");
  const results::JobResult& pcf = results.jobs[1];
  results.paper = {{pcf.id, "relmse", *pcf.metric("relmse") * 2, "", "Paper A", "", 0.1}};
  results::RunResults previous = previousRun();
  results::JobResult gone = previous.jobs[1];
  gone.id = "cornell-direct/shadow=hard,light_samples=4";
  previous.jobs.push_back(gone);

  const std::string summary = summaryOf(results, previous);
  EXPECT_THAT(summary, HasSubstr("1 failed"));
  EXPECT_THAT(summary, HasSubstr("1 paper value out of tolerance"));
  EXPECT_THAT(summary, HasSubstr("**1 regression** (1 job)"));  // the missing job
  EXPECT_THAT(unescaped(summary), HasSubstr("- " + failed.id + ": " + failed.failure));
  const auto regressions = table(summary, "### Regressions");
  ASSERT_EQ(regressions.size(), 1u) << summary;
  EXPECT_EQ(regressions[0][0], gone.id);
  EXPECT_EQ(regressions[0][3], "missing");
  const auto paper = table(summary, "### Paper values out of tolerance");
  ASSERT_EQ(paper.size(), 1u) << summary;
  EXPECT_EQ(paper[0],
            (std::vector<std::string>{pcf.id, "relmse", formatNumber(results.paper[0].value),
                                      formatNumber(*pcf.metric("relmse")), "±10%", "Paper A"}));
}

}  // namespace
}  // namespace gib::reports
