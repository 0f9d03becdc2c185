// The smoke suite's report and a figure suite's, end to end: `gibench run` on suites/smoke.toml
// and suites/figures/barsi-jakab-fig6.toml (shrunk to 32x32 and 64 spp so the test stays quick,
// everything else as shipped), then every page of their reports in headless Chromium (index, job
// pages, figure pages): no console errors, every image and viewer ready and every chart drawn.
#include "results/results.h"
#include "results/results_json.h"
#include "support/headless_browser.h"
#include "support/run_command.h"
#include "support/shrunk_smoke_suite.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <fstream>

namespace gib {
namespace {

namespace fs = std::filesystem;

// Every page of the report in `run`: index.html and report/*.html.
void expectEveryPageLoads(const fs::path& chromium, const fs::path& run, const fs::path& work) {
  std::vector<fs::path> pages = {run / "index.html"};
  for (const fs::directory_entry& entry : fs::directory_iterator(run / "report"))
    if (entry.path().extension() == ".html") pages.push_back(entry.path());
  for (const fs::path& page : pages) {
    SCOPED_TRACE(page.string());
    const test::LoadedPage loaded = test::loadPage(chromium, page, work);
    ASSERT_EQ(loaded.exit_code, 0) << loaded.log;
    EXPECT_EQ(test::reportCheck(loaded.dom), "ok") << loaded.log;
    EXPECT_EQ(test::consoleProblems(loaded.log), std::vector<std::string>{}) << loaded.log;
  }
}

TEST(SmokeReport, EveryPageLoadsInABrowserAndPassesItsSelfCheck) {
  GIB_REQUIRE_CHROMIUM(chromium);
  test::TempDir dir;
  std::ofstream(dir / "smoke.toml") << test::shrunkSmokeSuite();
  const fs::path run = dir / "run";
  // Twice, so that the second report has a previous run to colour against and trend charts.
  for (const char* out : {"first", "run"}) {
    const test::CommandResult r =
        test::runGibench({"run", (dir / "smoke.toml").string(), "--out", (dir / out).string(),
                          "--store", (dir / "store").string()},
                         dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const results::RunResults results = results::readResultsFile(run);
  ASSERT_EQ(results.run.suite, "smoke");
  for (const results::JobResult& job : results.jobs)
    ASSERT_TRUE(fs::is_regular_file(run / "report" / (job.slug + ".html"))) << job.id;
  expectEveryPageLoads(*chromium, run, dir.path());
}

TEST(SmokeReport, EveryPageOfAFigureSuitesReportLoads) {
  GIB_REQUIRE_CHROMIUM(chromium);
  test::TempDir dir;
  std::ofstream(dir / "figure.toml") << test::shrunkFigureSuite("barsi-jakab-fig6");
  const fs::path run = dir / "run";
  const test::CommandResult r =
      test::runGibench({"run", (dir / "figure.toml").string(), "--out", run.string(), "--store",
                        (dir / "store").string(), "--no-history"},
                       dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const results::RunResults results = results::readResultsFile(run);
  ASSERT_FALSE(results.figures.empty());
  for (const results::FigureSpec& figure : results.figures)
    ASSERT_TRUE(fs::is_regular_file(run / "report" / ("figure-" + figure.name + ".html")))
        << figure.name;
  expectEveryPageLoads(*chromium, run, dir.path());
}

}  // namespace
}  // namespace gib
