// The history database as `gibench run`, `history`, `diff` and the report use it: runs come back
// exactly, re-appending does not duplicate, the filters select what they say, and files that are
// not ours are refused with a clear message.
#include "results/history_db.h"

#include "common/input_error.h"
#include "support/synthetic_results.h"
#include "support/temp_dir.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <cmath>
#include <fstream>
#include <limits>

namespace gib::results {
namespace {

namespace fs = std::filesystem;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

// A run of suite `suite` started at `started`, with jobs on two scenes and two techniques.
RunResults historyRun(const std::string& id, const std::string& suite, const std::string& started,
                      const std::string& commit, double relmse) {
  JobResult a =
      test::syntheticJob("cornell-direct", {{"relmse", relmse}, {"ssim", 0.9}}, {4.0, 4.1, 4.2});
  JobResult b = test::syntheticJob("chamber-direct", {{"relmse", 2 * relmse}});
  b.scene = "chamber";
  b.reference.key = "ref-chamber";
  JobResult c = test::syntheticJob("cornell-reference", {});
  c.technique = "reference";
  RunResults run = test::syntheticRun(id, {a, b, c});
  run.run.suite = suite;
  run.run.started = started;
  run.run.git_commit = commit;
  return run;
}

// A filter with the fields the test sets (designated initializers would warn about the others).
template <typename Set>
HistoryFilter where(Set set) {
  HistoryFilter filter;
  set(filter);
  return filter;
}

std::vector<std::string> ids(const std::vector<RunSummary>& runs) {
  std::vector<std::string> out;
  for (const RunSummary& r : runs) out.push_back(r.id);
  return out;
}

// Four runs of two suites over three days.
class HistoryDatabaseTest : public ::testing::Test {
 protected:
  void SetUp() override {
    HistoryDatabase db = HistoryDatabase::open(path());
    db.append(historyRun("r1", "smoke", "2026-11-20T23:59:59Z", "aaaa1111", 0.010));
    db.append(historyRun("r2", "nightly", "2026-11-21T02:00:00Z", "bbbb2222", 0.020));
    db.append(historyRun("r3", "smoke", "2026-11-21T10:00:00Z", "bbbb2222", 0.030));
    db.append(historyRun("r4", "smoke", "2026-11-22T00:00:00Z", "cccc3333", 0.040));
  }
  fs::path path() const { return dir_ / "history.sqlite"; }
  std::vector<std::string> runIds(const HistoryFilter& filter) {
    return ids(HistoryDatabase::open(path()).runs(filter));
  }

  test::TempDir dir_;
};

TEST(HistoryDatabase, AppendedRunsReadBackEqual) {
  test::TempDir dir;
  HistoryDatabase db = HistoryDatabase::open(dir / "sub" / "history.sqlite");
  const RunResults rich = test::richResults();
  const std::int64_t row = db.append(rich);
  EXPECT_EQ(db.run(row), rich);
  EXPECT_EQ(db.run(rich.run.id), rich);
  EXPECT_EQ(db.run(row + 1), std::nullopt);
  EXPECT_EQ(db.run("no-such-run"), std::nullopt);
  // And from another connection to the same file.
  EXPECT_EQ(HistoryDatabase::open(dir / "sub" / "history.sqlite").run(row), rich);
}

TEST(HistoryDatabase, ReappendingARunReplacesItAndKeepsItsRow) {
  test::TempDir dir;
  HistoryDatabase db = HistoryDatabase::open(dir / "history.sqlite");
  RunResults run = historyRun("r1", "smoke", "2026-11-20T10:00:00Z", "aaaa", 0.01);
  const std::int64_t row = db.append(run);
  db.append(historyRun("r2", "smoke", "2026-11-21T10:00:00Z", "bbbb", 0.01));
  run.jobs.pop_back();
  run.jobs[0].metrics[0].second = 0.5;
  EXPECT_EQ(db.append(run), row);
  EXPECT_EQ(db.run(row), run);
  EXPECT_EQ(db.runs({}).size(), 2u);
  HistoryFilter filter;
  filter.metric = "relmse";
  filter.job = "cornell-direct";
  filter.suite = "smoke";
  std::vector<MetricPoint> points = db.values(filter);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[1].run.id, "r1");
  EXPECT_EQ(points[1].value, 0.5);
  EXPECT_EQ(points[1].run.jobs, 2u);
}

TEST_F(HistoryDatabaseTest, RunsAreNewestFirstAndFilteredBySuiteCommitAndDate) {
  EXPECT_THAT(runIds({}), ElementsAre("r4", "r3", "r2", "r1"));
  EXPECT_THAT(runIds(where([](HistoryFilter& f) { f.suite = "smoke"; })),
              ElementsAre("r4", "r3", "r1"));
  EXPECT_THAT(runIds(where([](HistoryFilter& f) { f.commit = "bbbb"; })), ElementsAre("r3", "r2"));
  EXPECT_THAT(runIds(where([](HistoryFilter& f) { f.commit = "BBBB2222"; })),
              ElementsAre("r3", "r2"));
  EXPECT_THAT(runIds(where([](HistoryFilter& f) { f.commit = "bbb2"; })),
              ElementsAre());  // a prefix, not a substring
  EXPECT_THAT(runIds(where([](HistoryFilter& f) { f.since = "2026-11-21"; })),
              ElementsAre("r4", "r3", "r2"));
  EXPECT_THAT(runIds(where([](HistoryFilter& f) { f.until = "2026-11-21"; })),
              ElementsAre("r3", "r2", "r1"));  // inclusive
  EXPECT_THAT(runIds(where([](HistoryFilter& f) {
                f.since = "2026-11-21T02:00:00Z";
                f.until = "2026-11-21T09";
              })),
              ElementsAre("r2"));
  EXPECT_THAT(runIds(where([](HistoryFilter& f) {
                f.suite = "smoke";
                f.limit = 2;
              })),
              ElementsAre("r4", "r3"));
  const RunSummary newest =
      HistoryDatabase::open(path()).runs(where([](HistoryFilter& f) { f.limit = 1; })).at(0);
  EXPECT_EQ(newest.suite, "smoke");
  EXPECT_EQ(newest.git_commit, "cccc3333");
  EXPECT_EQ(newest.jobs, 3u);
  EXPECT_EQ(newest.row, 4);
}

TEST_F(HistoryDatabaseTest, RunsFilteredByTheirJobs) {
  HistoryDatabase db = HistoryDatabase::open(path());
  RunResults other = historyRun("r5", "smoke", "2026-11-23T00:00:00Z", "dddd", 0.1);
  other.jobs.erase(other.jobs.begin() + 1);  // no chamber job
  db.append(other);
  EXPECT_THAT(runIds(where([](HistoryFilter& f) { f.scene = "chamber"; })),
              ElementsAre("r4", "r3", "r2", "r1"));
  EXPECT_THAT(runIds(where([](HistoryFilter& f) {
                f.scene = "chamber";
                f.technique = "direct";
              })),
              ElementsAre("r4", "r3", "r2", "r1"));
  // One job must match every criterion: chamber has no reference job.
  EXPECT_THAT(runIds(where([](HistoryFilter& f) {
                f.scene = "chamber";
                f.technique = "reference";
              })),
              ElementsAre());
  EXPECT_THAT(runIds(where([](HistoryFilter& f) { f.job = "cornell-reference"; })),
              ElementsAre("r5", "r4", "r3", "r2", "r1"));
}

TEST_F(HistoryDatabaseTest, MetricValuesByJobSceneTechniqueAndMetric) {
  HistoryDatabase db = HistoryDatabase::open(path());
  std::vector<MetricPoint> relmse = db.values(where([](HistoryFilter& f) {
    f.suite = "smoke";
    f.metric = "relmse";
  }));
  ASSERT_EQ(relmse.size(), 6u);  // two jobs with relmse in each of three runs
  EXPECT_EQ(relmse[0].run.id, "r4");
  EXPECT_EQ(relmse[0].job, "cornell-direct");
  EXPECT_EQ(relmse[0].value, 0.04);
  EXPECT_EQ(relmse[1].job, "chamber-direct");
  EXPECT_EQ(relmse[1].scene, "chamber");
  EXPECT_EQ(relmse[1].value, 0.08);

  std::vector<MetricPoint> chamber = db.values(where([](HistoryFilter& f) {
    f.scene = "chamber";
    f.metric = "relmse";
  }));
  EXPECT_EQ(chamber.size(), 4u);
  std::vector<MetricPoint> by_job = db.values(where([](HistoryFilter& f) {
    f.commit = "bbbb";
    f.job = "cornell-direct";
    f.metric = "ssim";
  }));
  ASSERT_EQ(by_job.size(), 2u);
  EXPECT_EQ(by_job[0].run.id, "r3");
  EXPECT_EQ(db.values(where([](HistoryFilter& f) {
                f.technique = "reference";
                f.metric = "relmse";
              }))
                .size(),
            0u);
  // The median frame time is the metric frame_ms.
  std::vector<MetricPoint> frames = db.values(where([](HistoryFilter& f) {
    f.metric = "frame_ms";
    f.limit = 1;
  }));
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].job, "cornell-direct");
  EXPECT_DOUBLE_EQ(frames[0].value, 4.1);
  // The limit counts runs: every value of the two newest runs.
  EXPECT_EQ(db.values(where([](HistoryFilter& f) {
                f.metric = "relmse";
                f.limit = 2;
              }))
                .size(),
            4u);
  EXPECT_THROW(db.values({}), InputError);
}

TEST(HistoryDatabase, NonFiniteAndFullReferenceValuesAreStored) {
  test::TempDir dir;
  HistoryDatabase db = HistoryDatabase::open(dir / "history.sqlite");
  RunResults run = test::richResults();
  run.jobs[0].metrics[0].second = std::numeric_limits<double>::quiet_NaN();
  db.append(run);
  std::vector<MetricPoint> relmse = db.values(where([&](HistoryFilter& f) {
    f.job = run.jobs[0].id;
    f.metric = "relmse";
  }));
  ASSERT_EQ(relmse.size(), 1u);
  EXPECT_TRUE(std::isnan(relmse[0].value));
  std::vector<MetricPoint> psnr = db.values(where([](HistoryFilter& f) { f.metric = "psnr"; }));
  ASSERT_EQ(psnr.size(), 1u);
  EXPECT_EQ(psnr[0].value, std::numeric_limits<double>::infinity());
  std::vector<MetricPoint> full =
      db.values(where([](HistoryFilter& f) { f.metric = "full:relmse"; }));
  ASSERT_EQ(full.size(), 1u);
  EXPECT_EQ(full[0].value, 0.25);
  EXPECT_TRUE(std::isnan(db.run(run.run.id)->jobs[0].metrics[0].second));
}

TEST_F(HistoryDatabaseTest, PreviousAndRecentRunsOfASuite) {
  HistoryDatabase db = HistoryDatabase::open(path());
  EXPECT_EQ(db.previousRun("smoke", "2026-11-22T00:00:00Z")->run.id, "r3");
  EXPECT_EQ(db.previousRun("smoke", "2026-11-21T10:00:00Z")->run.id, "r1");
  EXPECT_EQ(db.previousRun("smoke", "2026-11-20T23:59:59Z"), std::nullopt);
  EXPECT_EQ(db.previousRun("nightly", "2026-11-22T00:00:00Z")->run.id, "r2");
  std::vector<RunResults> recent = db.recentRuns("smoke", "2026-11-22T00:00:00Z", 2);
  ASSERT_EQ(recent.size(), 2u);
  EXPECT_EQ(recent[0].run.id, "r3");  // oldest first
  EXPECT_EQ(recent[1].run.id, "r4");
  EXPECT_EQ(db.recentRuns("smoke", "2026-11-21T23:00:00Z", 10).size(), 2u);
  EXPECT_TRUE(db.recentRuns("absent", "2026-11-22T00:00:00Z", 10).empty());
}

TEST(HistoryDatabase, ReferenceKeysOfEveryRecordedJob) {
  test::TempDir dir;
  HistoryDatabase db = HistoryDatabase::open(dir / "history.sqlite");
  EXPECT_TRUE(db.referenceKeys().empty());
  db.append(test::richResults());
  db.append(historyRun("r1", "smoke", "2026-11-20T10:00:00Z", "aaaa", 0.01));
  EXPECT_EQ(db.referenceKeys(),
            (std::set<std::string>{"ref-chamber", "ref-key-direct", "ref-key-full"}));
}

TEST_F(HistoryDatabaseTest, MalformedDateBoundsAreInputErrors) {
  HistoryDatabase db = HistoryDatabase::open(path());
  for (const char* bad : {"22/11/2026", "2026-11-22T10:00:00+02:00", "yesterday", "2026-1-2"}) {
    try {
      db.runs(where([&](HistoryFilter& f) { f.since = bad; }));
      ADD_FAILURE() << bad;
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr("--since '" + std::string(bad) + "' is not a UTC date"));
    }
  }
  EXPECT_THROW(db.values(where([](HistoryFilter& f) {
    f.until = "tomorrow";
    f.metric = "relmse";
  })),
               InputError);
}

TEST(HistoryDatabase, DuplicateJobIdsAreRefused) {
  test::TempDir dir;
  HistoryDatabase db = HistoryDatabase::open(dir / "history.sqlite");
  RunResults run = historyRun("r1", "smoke", "2026-11-20T10:00:00Z", "aaaa", 0.01);
  run.jobs.push_back(run.jobs[0]);
  EXPECT_THROW(db.append(run), InputError);
  EXPECT_TRUE(db.runs({}).empty());
}

std::string openError(const fs::path& path) {
  try {
    HistoryDatabase::open(path);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "opened " << path;
  return {};
}

// A row written by another machine or damaged on a shared disk: its stored results are outside
// input. Found by fuzzing (fuzz/history_row_fuzzer.cpp): a number beyond a double's range escaped
// the JSON parser as an internal error.
TEST(HistoryDatabase, DamagedStoredResultsAreAnInputErrorNamingTheRun) {
  test::TempDir dir;
  const std::int64_t row = [&] {
    HistoryDatabase db = HistoryDatabase::open(dir / "history.sqlite");
    return db.append(historyRun("r1", "smoke", "2026-11-20T10:00:00Z", "aaa", 0.01));
  }();
  for (const char* stored : {R"({"schema_version": 1e999})", "{\"run\": ", ""}) {
    sqlite3* raw = nullptr;
    ASSERT_EQ(sqlite3_open((dir / "history.sqlite").c_str(), &raw), SQLITE_OK);
    sqlite3_stmt* update = nullptr;
    ASSERT_EQ(sqlite3_prepare_v2(raw, "UPDATE runs SET results_json = ?", -1, &update, nullptr),
              SQLITE_OK);
    sqlite3_bind_text(update, 1, stored, -1, SQLITE_TRANSIENT);
    ASSERT_EQ(sqlite3_step(update), SQLITE_DONE);
    sqlite3_finalize(update);
    sqlite3_close(raw);
    const HistoryDatabase db = HistoryDatabase::open(dir / "history.sqlite");
    try {
      db.run(row);
      ADD_FAILURE() << "no error for stored results '" << stored << "'";
    } catch (const InputError& error) {
      EXPECT_THAT(error.what(), HasSubstr("(run " + std::to_string(row) + ")"));
    }
  }
}

TEST(HistoryDatabase, RefusesFilesThatAreNotOurs) {
  test::TempDir dir;
  std::ofstream(dir / "garbage.sqlite") << std::string(4096, 'x');
  EXPECT_THAT(openError(dir / "garbage.sqlite"),
              HasSubstr("garbage.sqlite' is not a SQLite database"));

  sqlite3* raw = nullptr;
  ASSERT_EQ(sqlite3_open((dir / "newer.sqlite").c_str(), &raw), SQLITE_OK);
  sqlite3_exec(raw, "PRAGMA user_version = 2", nullptr, nullptr, nullptr);
  sqlite3_close(raw);
  EXPECT_THAT(openError(dir / "newer.sqlite"),
              HasSubstr("was written by a newer gibench (schema 2, this one reads 1); update "
                        "gibench"));

  ASSERT_EQ(sqlite3_open((dir / "other.sqlite").c_str(), &raw), SQLITE_OK);
  sqlite3_exec(raw, "CREATE TABLE photos (id INTEGER)", nullptr, nullptr, nullptr);
  sqlite3_close(raw);
  EXPECT_THAT(openError(dir / "other.sqlite"), HasSubstr("not a gibench history database"));
  EXPECT_THAT(openError(dir.path()), HasSubstr("is a directory"));
}

}  // namespace
}  // namespace gib::results
