// `gibench history` as a user runs it: the runs table, a metric's values, JSON, the filters, and
// a database that is missing or not ours.
#include "results/history_db.h"
#include "support/run_command.h"
#include "support/synthetic_results.h"
#include "support/temp_dir.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <limits>

namespace gib::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

results::RunResults recordedRun(const std::string& id, const std::string& suite,
                                const std::string& started, double relmse, bool dirty) {
  results::RunResults run =
      syntheticRun(id, {syntheticJob("cornell-direct", {{"relmse", relmse}}, {4, 5, 6})});
  run.run.suite = suite;
  run.run.started = started;
  run.run.git_dirty = dirty;
  run.run.host = "nightly-box";
  run.run.gl_renderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
  return run;
}

// A store with three recorded runs: r1 smoke, r2 nightly (dirty), r3 smoke with a NaN relmse.
class HistoryCommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    results::HistoryDatabase db = results::HistoryDatabase::open(dir_ / "store" / "history.sqlite");
    db.append(recordedRun("r1", "smoke", "2026-11-20T10:00:00Z", 0.01, false));
    db.append(recordedRun("r2", "nightly", "2026-11-21T10:00:00Z", 0.02, true));
    db.append(recordedRun("r3", "smoke", "2026-11-22T10:00:00Z",
                          std::numeric_limits<double>::quiet_NaN(), false));
  }
  CommandResult history(std::vector<std::string> args) {
    args.insert(args.begin(), {"history", "--store", (dir_ / "store").string()});
    return runGibench(args, dir_.path());
  }

  TempDir dir_;
};

TEST_F(HistoryCommandTest, ListsRunsNewestFirst) {
  CommandResult r = history({});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(countLines(r.out), 4) << r.out;
  EXPECT_THAT(r.out, HasSubstr("row  id  suite    started"));
  const std::size_t r3 = r.out.find("3    r3  smoke");
  const std::size_t r2 = r.out.find("2    r2  nightly  2026-11-21T10:00:00Z  0123456789ab+dirty");
  const std::size_t r1 = r.out.find("1    r1  smoke");
  ASSERT_NE(r3, std::string::npos) << r.out;
  ASSERT_NE(r2, std::string::npos) << r.out;
  ASSERT_NE(r1, std::string::npos) << r.out;
  EXPECT_LT(r3, r2);
  EXPECT_LT(r2, r1);
  EXPECT_THAT(r.out, HasSubstr("nightly-box  llvmpipe (LLVM 15.0.6, 256 bits)  1\n"));
}

TEST_F(HistoryCommandTest, FiltersAndLimit) {
  CommandResult smoke = history({"--suite", "smoke", "--limit", "1"});
  ASSERT_EQ(smoke.exit_code, 0) << smoke.err;
  EXPECT_EQ(countLines(smoke.out), 2);
  EXPECT_THAT(smoke.out, HasSubstr(" r3 "));
  CommandResult dated = history({"--since", "2026-11-21", "--until", "2026-11-21"});
  EXPECT_EQ(countLines(dated.out), 2);
  EXPECT_THAT(dated.out, HasSubstr(" r2 "));
  CommandResult none = history({"--scene", "chamber"});
  EXPECT_EQ(none.exit_code, 0);
  EXPECT_THAT(none.out, HasSubstr("no recorded run matches"));
}

TEST_F(HistoryCommandTest, MetricValuesPerRunAndJob) {
  CommandResult r = history({"--metric", "relmse", "--suite", "smoke"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out,
              HasSubstr("row  started               commit        job             relmse\n"));
  EXPECT_THAT(r.out, HasSubstr("3    2026-11-22T10:00:00Z  0123456789ab  cornell-direct  nan\n"));
  EXPECT_THAT(r.out, HasSubstr("1    2026-11-20T10:00:00Z  0123456789ab  cornell-direct  0.01\n"));
  EXPECT_THAT(r.out, Not(HasSubstr("2026-11-21")));
  CommandResult frames = history({"--metric", "frame_ms", "--limit", "1"});
  EXPECT_THAT(frames.out, HasSubstr("cornell-direct  5\n"));
}

TEST_F(HistoryCommandTest, JsonIsOneObject) {
  CommandResult runs = history({"--json"});
  ASSERT_EQ(runs.exit_code, 0) << runs.err;
  EXPECT_EQ(countLines(runs.out), 1);
  const nlohmann::json j = nlohmann::json::parse(runs.out);
  ASSERT_EQ(j["runs"].size(), 3u);
  EXPECT_EQ(j["runs"][0]["id"], "r3");
  EXPECT_EQ(j["runs"][1]["git_dirty"], true);
  EXPECT_EQ(j["runs"][2]["jobs"], 1);

  CommandResult values = history({"--json", "--metric", "relmse"});
  const nlohmann::json v = nlohmann::json::parse(values.out);
  EXPECT_EQ(v["metric"], "relmse");
  ASSERT_EQ(v["values"].size(), 3u);
  EXPECT_EQ(v["values"][0]["value"], "nan");
  EXPECT_EQ(v["values"][2]["value"], 0.01);
  EXPECT_EQ(v["values"][2]["job"], "cornell-direct");
}

TEST_F(HistoryCommandTest, BadInputExitsWithCodeTwoAndOneLine) {
  std::ofstream(dir_ / "garbage.sqlite") << std::string(2048, 'g');
  fs::create_directory(dir_ / "empty");
  struct Case {
    std::vector<std::string> args;
    std::string message_part;
  };
  const std::vector<Case> cases = {
      {{"history", "--store", (dir_ / "empty").string()},
       "no run has been recorded in '" + (dir_ / "empty" / "history.sqlite").string() +
           "' (no history database there); choose one with --db FILE or --store DIR"},
      {{"history", "--db", (dir_ / "absent.sqlite").string()}, "no run has been recorded in"},
      {{"history", "--db", (dir_ / "garbage.sqlite").string()}, "is not a SQLite database"},
      {{"history", "--store", (dir_ / "store").string(), "--since", "last week"},
       "--since 'last week' is not a UTC date"},
      {{"history", "--store", (dir_ / "store").string(), "--limit", "-1"}, "--limit"},
  };
  for (const Case& c : cases) {
    CommandResult r = runGibench(c.args, dir_.path());
    EXPECT_EQ(r.exit_code, 2) << c.message_part << ": " << r.err;
    EXPECT_EQ(countLines(r.err), 1) << r.err;
    EXPECT_THAT(r.err, HasSubstr(c.message_part));
  }
  EXPECT_FALSE(fs::exists(dir_ / "empty" / "history.sqlite"));
}

}  // namespace
}  // namespace gib::test
