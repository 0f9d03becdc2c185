// `gibench report` as a user runs it: the report of a run directory, compared with the history
// database, and bad input.
#include "results/history_db.h"
#include "results/results_json.h"
#include "support/read_text.h"
#include "support/run_command.h"
#include "support/synthetic_report_run.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace gib::test {
namespace {

namespace fs = std::filesystem;

class ReportCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    results_ = syntheticReportResults();
    writeSyntheticRunDirectory(run_dir_, results_, dir_ / "store");  // no history database there
  }

  TempDir dir_;
  fs::path run_dir_ = dir_ / "run";
  results::RunResults results_;
};

TEST_F(ReportCommand, WritesTheReportAndPrintsThePathOfIndexHtml) {
  const CommandResult r = runGibench({"report", run_dir_.string()}, dir_.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, (run_dir_ / "index.html").string() + "\n");
  EXPECT_NE(r.err.find("no history database at"), std::string::npos) << r.err;
  EXPECT_NE(readText(run_dir_ / "index.html").find("GI Bench report: smoke"), std::string::npos);
  for (const results::JobResult& job : results_.jobs)
    EXPECT_TRUE(fs::is_regular_file(run_dir_ / "report" / (job.slug + ".html"))) << job.slug;
}

TEST_F(ReportCommand, ComparesWithThePreviousRunAndTrendsFromTheHistoryDatabase) {
  const fs::path db_path = dir_ / "history.sqlite";
  {
    results::RunResults previous =
        syntheticReportResults("20261121-100405-smoke-00000000", "fedcba9876543210");
    previous.run.started = "2026-11-21T10:04:05Z";
    previous.jobs[1].metrics[0].second = 0.001;  // relmse of the pcf job doubled since
    results::HistoryDatabase::open(db_path).append(previous);
  }
  const CommandResult r = runGibench(
      {"report", run_dir_.string(), "--db", db_path.string(), "--trend-runs", "5"}, dir_.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string index = readText(run_dir_ / "index.html");
  EXPECT_NE(index.find("20261121-100405-smoke-00000000"), std::string::npos);
  EXPECT_NE(index.find("class=\"job verdict-regressed\""), std::string::npos);
  EXPECT_NE(index.find("id=\"regressions\""), std::string::npos);
  const std::string page = readText(run_dir_ / "report" / (results_.jobs[1].slug + ".html"));
  EXPECT_NE(page.find("relmse over the last 2 runs"), std::string::npos);
  EXPECT_NE(page.find(">fedcba9<"), std::string::npos);
}

TEST_F(ReportCommand, BadInputExitsWithCodeTwoOneLineAndNoReport) {
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  fs::create_directories(dir_ / "empty");
  fs::create_directories(dir_ / "malformed");
  std::ofstream(dir_ / "malformed" / "results.json") << "{\"schema\": \"gibench-results\", ";
  const std::vector<Case> cases = {
      {{"report", (dir_ / "absent").string()}, "does not exist"},
      {{"report", (dir_ / "empty").string()}, "holds no results.json"},
      {{"report", (dir_ / "malformed").string()}, "results.json"},
      {{"report", run_dir_.string(), "--db", (dir_ / "none.sqlite").string()},
       "no run has been recorded"},
      {{"report", run_dir_.string(), "--trend-runs", "0"}, "--trend-runs"},
  };
  for (const Case& c : cases) {
    const CommandResult r = runGibench(c.args, dir_.path());
    EXPECT_EQ(r.exit_code, 2) << c.args.back() << ": " << r.err;
    EXPECT_EQ(countLines(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("gibench: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
  }
  for (const char* dir : {"empty", "malformed", "run"})
    EXPECT_FALSE(fs::exists(dir_ / dir / "index.html")) << dir;
}

}  // namespace
}  // namespace gib::test
