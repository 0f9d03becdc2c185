// `gibench diff` as a user (or `git bisect run`) runs it: exit codes, the human and JSON output,
// every form of run argument, and bad input.
#include "results/history_db.h"
#include "results/results_json.h"
#include "support/run_command.h"
#include "support/synthetic_results.h"
#include "support/temp_dir.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace gib::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

results::RunResults runWithRelmse(const std::string& id, double relmse) {
  return syntheticRun(id, {syntheticJob("cornell-direct", {{"relmse", relmse}, {"ssim", 0.9}},
                                        noisyFrameTimes(id.size(), 16, 5.0))});
}

// Two results files: base.json and, 10% worse in relmse, worse.json; same.json equals base.
class DiffCommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    results::writeResultsFile(dir_ / "base.json", runWithRelmse("base-run", 0.020));
    results::writeResultsFile(dir_ / "same.json", runWithRelmse("same-run", 0.020));
    results::writeResultsFile(dir_ / "worse.json", runWithRelmse("worse-run", 0.022));
  }
  std::string file(const char* name) const { return (dir_ / name).string(); }
  CommandResult diff(std::vector<std::string> args, const std::vector<std::string>& env = {}) {
    args.insert(args.begin(), "diff");
    return runGibench(args, dir_.path(), env);
  }

  TempDir dir_;
};

TEST_F(DiffCommandTest, ExitsZeroWhenNothingRegressed) {
  CommandResult r = diff({file("base.json"), file("same.json")});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("base base-run\nnew  same-run\n"));
  EXPECT_THAT(r.out, HasSubstr("0 regressions"));
  EXPECT_EQ(r.err, "");
}

TEST_F(DiffCommandTest, ExitsOneAndNamesTheRegression) {
  CommandResult r = diff({file("base.json"), file("worse.json")});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_THAT(r.out, HasSubstr("regressed   cornell-direct  relmse  0.02 -> 0.022  +10.0%"));
  EXPECT_THAT(r.out, HasSubstr("1 regression,"));
  // The other way round it is an improvement.
  EXPECT_EQ(diff({file("worse.json"), file("base.json")}).exit_code, 0);
}

TEST_F(DiffCommandTest, JsonIsOneObject) {
  CommandResult r = diff({file("base.json"), file("worse.json"), "--json"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(countLines(r.out), 1);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["regressions"], 1);
  EXPECT_EQ(j["base_run"], "base-run");
  EXPECT_EQ(j["metrics"][0]["verdict"], "regressed");
  EXPECT_EQ(j["timings"].size(), 1u);
}

TEST_F(DiffCommandTest, RunDirectoriesAndDatabaseRunsAreArguments) {
  fs::create_directory(dir_ / "run");
  results::writeResultsFile(dir_ / "run" / "results.json", runWithRelmse("dir-run", 0.022));
  EXPECT_EQ(diff({file("base.json"), file("run")}).exit_code, 1);

  fs::create_directory(dir_ / "store");
  {
    results::HistoryDatabase db = results::HistoryDatabase::open(dir_ / "store" / "history.sqlite");
    db.append(runWithRelmse("base-run", 0.020));   // row 1
    db.append(runWithRelmse("worse-run", 0.022));  // row 2
  }
  const std::string store = file("store");
  const std::string db = (dir_ / "store" / "history.sqlite").string();
  CommandResult by_row = diff({"1", "2", "--store", store});
  EXPECT_EQ(by_row.exit_code, 1) << by_row.err;
  EXPECT_THAT(by_row.out, HasSubstr("new  worse-run"));
  EXPECT_EQ(diff({"base-run", "worse-run", "--db", db}).exit_code, 1);
  EXPECT_EQ(diff({"2", "1", "--db", db}).exit_code, 0);
  // A file against a database run, and the default store from the environment.
  EXPECT_EQ(diff({file("same.json"), "2"}, {"GIBENCH_STORE=" + store}).exit_code, 1);
}

TEST_F(DiffCommandTest, BadInputExitsWithCodeTwoAndOneLine) {
  std::ofstream(dir_ / "other.json") << R"({"hello": "world"})";
  std::ofstream(dir_ / "garbage.sqlite") << std::string(2048, 'g');
  fs::create_directory(dir_ / "empty-store");
  { results::HistoryDatabase::open(dir_ / "history.sqlite").append(runWithRelmse("a", 1)); }
  const std::string db = (dir_ / "history.sqlite").string();
  struct Case {
    std::vector<std::string> args;
    std::string message_part;
  };
  const std::vector<Case> cases = {
      {{file("base.json"), file("absent.json")}, "absent.json' does not exist"},
      {{file("base.json"), file("other.json")}, "other.json: schema: missing"},
      {{file("base.json"), "7", "--db", db}, "'7' is neither a file nor a run in the history"},
      {{file("base.json"), "no-such-run", "--db", db}, "`gibench history` lists"},
      {{file("base.json"), "3", "--store", file("empty-store")}, "there is no history database at"},
      {{file("base.json"), "1", "--db", file("garbage.sqlite")}, "is not a SQLite database"},
      {{file("base.json")}, "new is required"},
  };
  for (const Case& c : cases) {
    CommandResult r = diff(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.message_part << ": " << r.err;
    EXPECT_EQ(countLines(r.err), 1) << r.err;
    EXPECT_THAT(r.err, HasSubstr(c.message_part));
    EXPECT_EQ(r.out, "");
  }
  // Reading commands create no database.
  EXPECT_FALSE(fs::exists(dir_ / "empty-store" / "history.sqlite"));
}

}  // namespace
}  // namespace gib::test
