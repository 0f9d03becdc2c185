// scripts/report-load-time.py, which gives the report's page weight and load time in the
// benchmark notes: it measures a real report in Chromium, and refuses bad input with one line.
#include "reports/html_report.h"

#include "common/subprocess.h"
#include "support/headless_browser.h"
#include "support/synthetic_report_run.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

namespace gib::reports {
namespace {

namespace fs = std::filesystem;

ProgramResult runScript(const std::vector<std::string>& args, const fs::path& work_dir) {
  std::vector<std::string> argv = {"python3",
                                   std::string(GIB_SOURCE_DIR) + "/scripts/report-load-time.py"};
  argv.insert(argv.end(), args.begin(), args.end());
  return runProgram(argv, work_dir, {});
}

TEST(ReportLoadTimeScript, MeasuresTheIndexAndTheHeaviestJobPage) {
  GIB_REQUIRE_CHROMIUM(chromium);
  test::TempDir dir;
  const results::RunResults results = test::syntheticReportResults();
  test::writeSyntheticOutputs(dir.path(), results);
  writeHtmlReport(dir.path(), results, {});
  const ProgramResult r = runScript(
      {dir.path().string(), "--repeat", "1", "--chromium", chromium->string()}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("index.html"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("report/"), std::string::npos) << r.out;
  const auto pages =
      std::count_if(fs::directory_iterator(dir.path() / "report"), fs::directory_iterator(),
                    [](const fs::directory_entry& e) { return e.path().extension() == ".html"; });
  EXPECT_NE(r.out.find(std::to_string(pages) + " pages under report/"), std::string::npos) << r.out;
}

TEST(ReportLoadTimeScript, BadInputIsOneLineAndExitTwo) {
  test::TempDir dir;
  std::ofstream(dir.path() / "index.html") << "<!DOCTYPE html>";  // a report, but no browser
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{(dir.path() / "absent").string()},
        std::vector<std::string>{dir.path().string(), "--chromium", "/nonexistent/chromium"}}) {
    const ProgramResult r = runScript(args, dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

}  // namespace
}  // namespace gib::reports
