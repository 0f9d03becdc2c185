// `--junit FILE` and `--summary FILE` as a CI job uses them: written by `gibench report` from a
// synthetic run directory and by `gibench run` at the end of a run; bad paths refused by `report`,
// `merge` and `run` before anything is written.
#include "results/history_db.h"
#include "results/results_json.h"
#include "support/read_text.h"
#include "support/run_command.h"
#include "support/synthetic_report_run.h"
#include "support/temp_dir.h"
#include "support/tiny_suite.h"
#include "support/xml_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace gib::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class CiOutputs : public ::testing::Test {
 protected:
  void SetUp() override {
    results_ = syntheticReportResults();
    writeSyntheticRunDirectory(run_dir_, results_, dir_ / "store");  // no history database there
  }

  // A history database whose previous run of the suite had half the pcf job's relmse.
  fs::path historyWithARegression() const {
    const fs::path db = dir_ / "history.sqlite";
    results::RunResults previous =
        syntheticReportResults("20261121-100405-smoke-00000000", "fedcba9876543210");
    previous.run.started = "2026-11-21T10:04:05Z";
    previous.jobs[1].metrics[0].second /= 2;
    results::HistoryDatabase::open(db).append(previous);
    return db;
  }

  // Refused with exit code 2 and one line naming `message`, nothing written.
  void expectRefused(const std::vector<std::string>& args, const std::string& message) const {
    const CommandResult r = runGibench(args, dir_.path());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(countLines(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("gibench: ", 0), 0u) << r.err;
    EXPECT_THAT(r.err, HasSubstr(message));
    EXPECT_FALSE(fs::exists(run_dir_ / "index.html"));
    EXPECT_FALSE(fs::exists(run_dir_ / "report"));
    for (const fs::directory_entry& entry : fs::directory_iterator(dir_.path()))
      EXPECT_TRUE(entry.path() == run_dir_ || entry.path().filename() == "folder.xml")
          << "written: " << entry.path();
  }

  TempDir dir_;
  fs::path run_dir_ = dir_ / "run";
  results::RunResults results_;
};

TEST_F(CiOutputs, ReportWritesJunitAndSummaryBesideTheReport) {
  const fs::path junit = dir_ / "out.xml", summary = dir_ / "out.md";
  const CommandResult r =
      runGibench({"report", run_dir_.string(), "--db", historyWithARegression().string(), "--junit",
                  junit.string(), "--summary", summary.string()},
                 dir_.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, (run_dir_ / "index.html").string() + "\n");
  EXPECT_TRUE(fs::is_regular_file(run_dir_ / "index.html"));

  const XmlElement root = parseXml(readText(junit));
  const XmlElement* suite = root.child("testsuite");
  ASSERT_NE(suite, nullptr);
  EXPECT_EQ(suite->at("tests"), std::to_string(results_.jobs.size()));
  EXPECT_EQ(suite->at("failures"), "1");
  for (const XmlElement* test_case : suite->childrenNamed("testcase"))
    EXPECT_EQ(test_case->child("failure") != nullptr, test_case->at("name") == results_.jobs[1].id)
        << test_case->at("name");

  const std::string markdown = readText(summary);
  EXPECT_THAT(markdown, HasSubstr("**1 regression** (1 job)"));
  EXPECT_THAT(markdown, HasSubstr("### Regressions"));
  EXPECT_THAT(markdown, HasSubstr(results_.run.id));
}

TEST_F(CiOutputs, BadPathsAreRefusedBeforeAnythingIsWritten) {
  fs::create_directories(dir_ / "folder.xml");
  const std::string run = run_dir_.string();
  expectRefused({"report", run, "--junit", (dir_ / "missing" / "out.xml").string()},
                "--junit: cannot write");
  expectRefused({"report", run, "--junit", (dir_ / "out.txt").string()}, "must end in .xml");
  expectRefused({"report", run, "--summary", (dir_ / "out.xml").string()}, "must end in .md");
  expectRefused({"report", run, "--junit", (dir_ / "folder.xml").string()}, "is a directory");
  expectRefused({"report", run, "--junit", (dir_ / "out.xml").string(), "--summary",
                 (dir_ / "missing" / "out.md").string()},
                "--summary: cannot write");
  expectRefused({"merge", run, "--store", (dir_ / "store").string(), "--junit",
                 (dir_ / "missing" / "out.xml").string()},
                "--junit: cannot write");

  std::ofstream(dir_ / "tiny.toml") << kTinySuite;
  const fs::path out = dir_ / "tiny-run";
  auto runTiny = [&](std::vector<std::string> more) {
    std::vector<std::string> args = {"run",     (dir_ / "tiny.toml").string(),
                                     "--out",   out.string(),
                                     "--store", (dir_ / "store").string()};
    args.insert(args.end(), more.begin(), more.end());
    return runGibench(args, dir_.path());
  };
  for (const std::vector<std::string>& more :
       {std::vector<std::string>{"--junit", (dir_ / "missing" / "out.xml").string()},
        std::vector<std::string>{"--shard", "1/2", "--summary", (dir_ / "out.md").string()}}) {
    const CommandResult r = runTiny(more);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(countLines(r.err), 1) << r.err;
    EXPECT_FALSE(fs::exists(out)) << more[0];
    EXPECT_FALSE(fs::exists(dir_ / "out.md"));
  }
}

TEST_F(CiOutputs, ARunWritesThemAtItsEnd) {
  std::ofstream(dir_ / "tiny.toml") << kTinySuite;
  const fs::path out = dir_ / "tiny-run", junit = dir_ / "tiny.xml", summary = dir_ / "tiny.md";
  const CommandResult r = runGibench(
      {"run", (dir_ / "tiny.toml").string(), "--out", out.string(), "--store",
       (dir_ / "store").string(), "--junit", junit.string(), "--summary", summary.string()},
      dir_.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("junit      " + junit.string()));
  EXPECT_THAT(r.out, HasSubstr("summary    " + summary.string()));
  const results::RunResults results = results::readResultsFile(out / "results.json");
  const XmlElement root = parseXml(readText(junit));
  const XmlElement* suite = root.child("testsuite");
  ASSERT_NE(suite, nullptr);
  EXPECT_EQ(suite->at("name"), "tiny");
  EXPECT_EQ(suite->at("tests"), std::to_string(results.jobs.size()));
  EXPECT_EQ(suite->at("failures"), "0");
  EXPECT_EQ(suite->at("errors"), "0");
  // The first run of the suite in this history: nothing to compare with.
  EXPECT_THAT(readText(summary), HasSubstr("so no regressions"));
}

}  // namespace
}  // namespace gib::test
