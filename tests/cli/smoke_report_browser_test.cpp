// The smoke suite's report, end to end: `gibench run` on suites/smoke.toml (shrunk to 32x32 and
// 64 spp so the test stays quick, everything else as shipped), then every page of its report in
// headless Chromium: no console errors, every image decoded and every chart drawn.
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
  std::vector<fs::path> pages = {run / "index.html"};
  for (const results::JobResult& job : results.jobs)
    pages.push_back(run / "report" / (job.slug + ".html"));
  for (const fs::path& page : pages) {
    SCOPED_TRACE(page.string());
    ASSERT_TRUE(fs::is_regular_file(page));
    const test::LoadedPage loaded = test::loadPage(*chromium, page, dir.path());
    ASSERT_EQ(loaded.exit_code, 0) << loaded.log;
    EXPECT_EQ(test::reportCheck(loaded.dom), "ok") << loaded.log;
    EXPECT_EQ(test::consoleProblems(loaded.log), std::vector<std::string>{}) << loaded.log;
  }
}

}  // namespace
}  // namespace gib
