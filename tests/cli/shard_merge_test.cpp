// `gibench run --shard i/n` and `gibench merge`: the slices of a suite run apart (in one shared
// directory or in one directory each) assemble into the results a local run writes; a job that
// fails in a shard is recorded and shown, not lost; bad input stops before anything is written.
#include "results/results.h"
#include "results/results_json.h"
#include "support/run_command.h"
#include "support/run_equivalence.h"
#include "support/temp_dir.h"
#include "support/tiny_suite.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

namespace gib {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class ShardMergeTest : public ::testing::Test {
 protected:
  ShardMergeTest() { std::ofstream(suite()) << test::kTinySuite; }

  fs::path suite() const { return dir_ / "tiny.toml"; }
  fs::path store() const { return dir_ / "store"; }

  test::CommandResult gibench(std::vector<std::string> args) const {
    args.push_back("--store");
    args.push_back(store().string());
    return test::runGibench(args, dir_.path());
  }
  test::CommandResult shard(const fs::path& out, const std::string& slice,
                            std::vector<std::string> more = {}) const {
    std::vector<std::string> args = {"run", suite().string(), "--out", out.string(), "--shard",
                                     slice, "--no-history"};
    args.insert(args.end(), more.begin(), more.end());
    return gibench(args);
  }

  test::TempDir dir_;
};

TEST_F(ShardMergeTest, ShardsInOneDirectoryMergeIntoTheLocalRunsResults) {
  const test::CommandResult local =
      gibench({"run", suite().string(), "--out", (dir_ / "local").string(), "--no-history"});
  ASSERT_EQ(local.exit_code, 0) << local.err;
  const fs::path out = dir_ / "sharded";
  for (const char* slice : {"2/2", "1/2"}) {
    const test::CommandResult r = shard(out, slice);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("gibench merge"));
    EXPECT_FALSE(fs::exists(out / "results.json")) << "a shard assembles nothing";
  }
  const test::CommandResult merged =
      gibench({"merge", out.string(), "--db", (dir_ / "h.sqlite").string()});
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_THAT(merged.out, HasSubstr("history    run 1"));
  for (const char* file : {"results.json", "results.csv", "index.html"})
    EXPECT_TRUE(fs::is_regular_file(out / file)) << file;
  const results::RunResults a = results::readResultsFile(dir_ / "local" / "results.json");
  const results::RunResults b = results::readResultsFile(out / "results.json");
  test::expectSameDeterministicResults(a, b);
  for (const results::JobResult& job : b.jobs) EXPECT_FALSE(job.execution.host.empty());
  // The suite's figure survives the merge, with its page and picture.
  ASSERT_EQ(b.figures.size(), 1u);
  EXPECT_TRUE(fs::is_regular_file(out / "report" / "figure-shadows.html"));
  EXPECT_TRUE(fs::is_regular_file(out / "figures" / "shadows.png"));
}

TEST_F(ShardMergeTest, ShardsInTheirOwnDirectoriesAreGatheredByTheMerge) {
  // As a CI matrix runs them: each shard on its machine, each directory an artifact.
  for (const char* slice : {"1/3", "2/3", "3/3"}) {
    const std::string name = std::string("part") + slice[0];
    const test::CommandResult r = shard(dir_ / name, slice);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const fs::path out = dir_ / "whole";
  const test::CommandResult merged =
      gibench({"merge", (dir_ / "part1").string(), (dir_ / "part2").string(),
               (dir_ / "part3").string(), "--out", out.string(), "--no-history"});
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  const results::RunResults results = results::readResultsFile(out / "results.json");
  ASSERT_EQ(results.jobs.size(), 3u);
  for (const results::JobResult& job : results.jobs) {
    EXPECT_FALSE(job.failed()) << job.id << ": " << job.failure;
    EXPECT_TRUE(fs::is_regular_file(out / job.outputs.reference_png)) << job.id;
    // The report viewer's data, the reference's shared file included, came along.
    EXPECT_TRUE(fs::is_regular_file(out / job.outputs.viewer_data)) << job.id;
    EXPECT_TRUE(fs::is_regular_file(out / job.outputs.reference_viewer_data)) << job.id;
  }
}

TEST_F(ShardMergeTest, AFailedJobIsRecordedShownAndRunAgainOnResume) {
  const fs::path out = dir_ / "run";
  // The technique jobs cannot get their GL device; the reference job is unaffected.
  const test::CommandResult broken = shard(out, "1/1", {"--gl-device", "99"});
  EXPECT_EQ(broken.exit_code, 1);
  EXPECT_THAT(broken.out, HasSubstr("2 failed"));
  const test::CommandResult merged = gibench({"merge", out.string(), "--no-history"});
  EXPECT_EQ(merged.exit_code, 1);
  EXPECT_THAT(merged.err, HasSubstr("2 of 3 jobs failed"));
  const results::RunResults results = results::readResultsFile(out / "results.json");
  ASSERT_EQ(results.jobs.size(), 3u);
  EXPECT_FALSE(results.jobs[0].failed());
  for (std::size_t i : {1u, 2u}) {
    EXPECT_THAT(results.jobs[i].failure, HasSubstr("GL device 99"));
    EXPECT_TRUE(results.jobs[i].metrics.empty());
  }
  std::ifstream page(out / "report" / (results.jobs[1].slug + ".html"));
  const std::string html{std::istreambuf_iterator<char>(page), std::istreambuf_iterator<char>()};
  EXPECT_THAT(html, HasSubstr("The job failed"));

  // The failed jobs run again; the finished one is kept.
  const test::CommandResult resumed = shard(out, "1/1");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_THAT(resumed.err, HasSubstr("finished by an earlier attempt"));
  ASSERT_EQ(gibench({"merge", out.string(), "--no-history"}).exit_code, 0);
  for (const results::JobResult& job : results::readResultsFile(out / "results.json").jobs)
    EXPECT_FALSE(job.failed()) << job.id;
}

TEST_F(ShardMergeTest, BadInputStopsBeforeAnythingIsWritten) {
  struct Case {
    std::vector<std::string> args;
    const char* message;
  };
  const std::string out = (dir_ / "never").string();
  const std::vector<Case> cases = {
      {{"run", suite().string(), "--out", out, "--shard", "3/2"}, "--shard '3/2' is not a slice"},
      {{"run", suite().string(), "--out", out, "--shard", "0/2"}, "--shard '0/2' is not a slice"},
      {{"run", suite().string(), "--out", out, "--shard", "1/x"}, "--shard '1/x' is not a slice"},
      {{"run", suite().string(), "--out", out, "--shard", "1/2", "--slurm"},
       "--slurm and --shard contradict"},
      {{"run", suite().string(), "--out", out, "--wait"}, "go with --slurm"},
      {{"run", suite().string(), "--out", out, "--partition-gpu", "gpu"}, "go with --slurm"},
      {{"run", suite().string(), "--out", out, "--task-list", (dir_ / "none").string(),
        "--task-index", "0"},
       "cannot read the task list"},
      {{"merge", (dir_ / "nope").string()}, "dirs: Directory does not exist"},
      {{"merge", dir_.path().string()}, "holds no gibench run"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.args[0] + " " + c.args.back());
    const test::CommandResult r = gibench(c.args);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_THAT(r.err, HasSubstr(c.message));
    EXPECT_EQ(test::countLines(r.err), 1) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST_F(ShardMergeTest, RunsOfDifferentSuitesDoNotMerge) {
  ASSERT_EQ(shard(dir_ / "a", "1/2").exit_code, 0);
  std::string other = test::kTinySuite;
  other.replace(0, 13, "name = \"other\"");
  std::ofstream(dir_ / "other.toml") << other;
  ASSERT_EQ(gibench({"run", (dir_ / "other.toml").string(), "--out", (dir_ / "b").string(),
                     "--shard", "2/2", "--no-history"})
                .exit_code,
            0);
  const test::CommandResult r =
      gibench({"merge", (dir_ / "a").string(), (dir_ / "b").string(), "--no-history"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("merge runs of one suite"));
}

}  // namespace
}  // namespace gib
