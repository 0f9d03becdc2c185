// `gibench run --slurm` on a real Slurm: a one-node cluster started by scripts/slurm-local.sh
// (munge, slurmctld, slurmd from Debian's packages), never a mock. One test, because the cluster
// is one per machine and its start costs seconds: the smoke suite submitted, which must merge into
// a local run's results, then on a tiny suite a cancelled task and its resume, a task that fails,
// two suites sharing a store, and the bad input that must stop before anything is submitted.
#include "results/results.h"
#include "results/results_json.h"
#include "support/headless_browser.h"
#include "support/read_text.h"
#include "support/run_command.h"
#include "support/run_equivalence.h"
#include "support/shrunk_smoke_suite.h"
#include "support/temp_dir.h"
#include "support/tiny_suite.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <regex>
#include <thread>

namespace gib {
namespace {

namespace fs = std::filesystem;
using test::readText;
using ::testing::HasSubstr;
using ::testing::Not;

// The cluster of scripts/slurm-local.sh, state under `dir`, stopped when this goes away.
class LocalSlurm {
 public:
  explicit LocalSlurm(const fs::path& dir) : dir_(dir) {
    const ProgramResult started = run("start");
    const std::smatch match = search(started.out, std::regex("export SLURM_CONF=(\\S+)"));
    if (started.exit_code != 0 || match.empty())
      throw std::runtime_error("slurm-local.sh start failed: " + started.err);
    conf_ = match[1];
  }
  ~LocalSlurm() { run("stop", "--clean"); }
  LocalSlurm(const LocalSlurm&) = delete;
  LocalSlurm& operator=(const LocalSlurm&) = delete;

  std::vector<std::string> environment() const { return {"SLURM_CONF=" + conf_}; }
  ProgramResult command(const std::vector<std::string>& argv) const {
    return runProgram(argv, dir_, environment());
  }

 private:
  static std::smatch search(const std::string& text, const std::regex& pattern) {
    std::smatch match;
    std::regex_search(text, match, pattern);
    return match;
  }
  ProgramResult run(const char* action, const char* option = nullptr) const {
    std::vector<std::string> argv = {
        "bash", (fs::path(GIB_SOURCE_DIR) / "scripts" / "slurm-local.sh").string(), action};
    if (option) argv.push_back(option);
    return runProgram(argv, dir_, {"GIB_SLURM_DIR=" + (dir_ / "cluster").string()});
  }
  fs::path dir_;
  std::string conf_;
};

// Skips where no cluster can be started (not root, no Slurm), saying why, unless the test run
// requires it: scripts/test.sh sets GIB_REQUIRE_SLURM=1 where it runs as root, and CI (.ci/run,
// which runs as root) sets it outright, so that a CI without root fails here rather than skips.
bool slurmUnavailable(std::string* why) {
  if (geteuid() != 0)
    *why = "not root: scripts/slurm-local.sh starts slurmd, which runs jobs as any user";
  else if (!fs::exists("/usr/sbin/slurmctld") || !fs::exists("/usr/bin/sbatch"))
    *why = "no Slurm (slurmctld, sbatch); scripts/install-deps.sh installs it";
  return !why->empty();
}

class SlurmRun : public ::testing::Test {
 protected:
  SlurmRun() {
    std::ofstream(suite()) << test::kTinySuite;
    std::ofstream(dir_ / "smoke.toml") << test::shrunkSmokeSuite();
    std::string other = test::kTinySuite;
    std::ofstream(dir_ / "other.toml") << other.replace(0, 13, "name = \"other\"");
  }

  fs::path suite() const { return dir_ / "tiny.toml"; }

  test::CommandResult gibench(const std::vector<std::string>& args) const {
    return test::runGibench(args, dir_.path(), slurm_->environment());
  }
  // `gibench run SUITE --slurm` into `out` with the store `store` and `more` options.
  test::CommandResult submit(const fs::path& suite_file, const fs::path& out, const fs::path& store,
                             std::vector<std::string> more = {}) const {
    std::vector<std::string> args = {"run",          suite_file.string(), "--slurm",
                                     "--out",        out.string(),        "--store",
                                     store.string(), "--no-history",      "--partition-cpu",
                                     "cpu",          "--partition-gpu",   "gpu"};
    args.insert(args.end(), more.begin(), more.end());
    return gibench(args);
  }
  // The exit status the merge job of submission `n` of the run in `out` wrote, once it has.
  int awaitMerge(const fs::path& out, int n = 1) const {
    const fs::path status = out / "slurm" / std::to_string(n) / "merge.status";
    for (int waited = 0; waited < 600 && !fs::exists(status); ++waited)
      std::this_thread::sleep_for(std::chrono::seconds(1));
    std::ifstream in(status);
    int code = -1;
    in >> code;
    return code;
  }
  std::string slurmJobId(const fs::path& out, const char* key, int n = 1) const {
    const std::string text = readText(out / "slurm" / std::to_string(n) / "submission.json");
    std::smatch match;
    std::regex_search(text, match, std::regex(std::string("\"") + key + "\": \"(\\d+)\""));
    return match.empty() ? std::string() : std::string(match[1]);
  }
  // Lines saying a reference was rendered (not found in the store) in every task log of `out`.
  int referencesRendered(const fs::path& out) const {
    int count = 0;
    for (const auto& entry : fs::recursive_directory_iterator(out / "slurm"))
      if (entry.path().extension() == ".log") {
        const std::string log = readText(entry.path());
        const std::regex rendered(R"(: reference [^\n]*: rendered in)");
        count += int(std::distance(std::sregex_iterator(log.begin(), log.end(), rendered),
                                   std::sregex_iterator()));
      }
    return count;
  }

  test::TempDir dir_;
  std::unique_ptr<LocalSlurm> slurm_;
};

TEST_F(SlurmRun, ArraysMergeLikeALocalRunSurviveCancelAndFailureAndShareTheStore) {
  std::string why;
  if (slurmUnavailable(&why)) {
    const char* required = std::getenv("GIB_REQUIRE_SLURM");
    if (required && std::string(required) == "1") FAIL() << "GIB_REQUIRE_SLURM=1 but " << why;
    GTEST_SKIP() << "SlurmRun skipped, gibench run --slurm untested: " << why
                 << ". CI runs it as root and requires it (GIB_REQUIRE_SLURM=1 makes this skip a "
                    "failure)";
  }
  slurm_ = std::make_unique<LocalSlurm>(dir_.path());

  {
    SCOPED_TRACE("bad input: exit 2, one line, nothing submitted or written");
    const fs::path out = dir_ / "never";
    const test::CommandResult unknown =
        gibench({"run", suite().string(), "--slurm", "--out", out.string(), "--no-history",
                 "--partition-gpu", "nosuch"});
    EXPECT_EQ(unknown.exit_code, 2) << unknown.out << unknown.err;
    EXPECT_THAT(unknown.err, HasSubstr("Slurm has no partition 'nosuch'"));
    EXPECT_EQ(test::countLines(unknown.err), 1) << unknown.err;
    EXPECT_FALSE(fs::exists(out));
    const test::CommandResult no_sbatch = test::runGibench(
        {"run", suite().string(), "--slurm", "--out", out.string(), "--no-history"}, dir_.path(),
        {"PATH=/nonexistent"});
    EXPECT_EQ(no_sbatch.exit_code, 2);
    EXPECT_THAT(no_sbatch.err, HasSubstr("--slurm needs Slurm's `sbatch` on PATH"));
    EXPECT_FALSE(fs::exists(out));
  }

  std::vector<fs::path> smoke_pages;  // checked in the browser last (it may skip the test)
  {
    SCOPED_TRACE(
        "the smoke suite with --slurm --wait: three sbatch calls, references first, the "
        "local run's results");
    const fs::path smoke = dir_ / "smoke.toml";
    const test::CommandResult local =
        gibench({"run", smoke.string(), "--out", (dir_ / "smoke-local").string(), "--store",
                 (dir_ / "local-store").string(), "--no-history"});
    ASSERT_EQ(local.exit_code, 0) << local.err;
    const fs::path out = dir_ / "smoke-slurm";
    const test::CommandResult r = submit(smoke, out, dir_ / "smoke-store", {"--wait"});
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    // The reference job, and the LE|LDE reference of the direct jobs (stochastic radiosity is
    // measured against the full reference, which the reference job renders).
    EXPECT_THAT(r.out, HasSubstr("reference array (2 tasks)"));
    EXPECT_THAT(r.out, HasSubstr("technique array (4 tasks)"));
    EXPECT_THAT(readText(out / "slurm" / "1" / "submission.json"),
                HasSubstr("\"sbatch_calls\": 3"));
    const results::RunResults merged = results::readResultsFile(out / "results.json");
    test::expectSameDeterministicResults(
        results::readResultsFile(dir_ / "smoke-local" / "results.json"), merged);
    for (const results::JobResult& job : merged.jobs) {
      EXPECT_THAT(job.execution.scheduler_job, testing::MatchesRegex("[0-9]+_[0-9]+")) << job.id;
      EXPECT_GE(job.execution.queue_seconds, 0) << job.id;
      if (job.technique == "reference") continue;
      // The CPU array rendered every reference before the technique array started.
      EXPECT_TRUE(job.reference.store_hit) << job.id;
      if (job.full_reference) {
        EXPECT_TRUE(job.full_reference->store_hit) << job.id;
      }
      EXPECT_FALSE(job.execution.gl_renderer.empty()) << job.id;
    }
    smoke_pages.push_back(out / "index.html");
    for (const results::JobResult& job : merged.jobs)
      smoke_pages.push_back(out / "report" / (job.slug + ".html"));
  }

  // The tiny suite's local run, for the scenarios below.
  const test::CommandResult local =
      gibench({"run", suite().string(), "--out", (dir_ / "local").string(), "--store",
               (dir_ / "local-store").string(), "--no-history"});
  ASSERT_EQ(local.exit_code, 0) << local.err;
  const results::RunResults expected = results::readResultsFile(dir_ / "local" / "results.json");

  {
    SCOPED_TRACE(
        "a cancelled task: its job shows as failed, also in the merge's --junit; --resume runs "
        "it alone");
    const fs::path out = dir_ / "cancelled";
    const test::CommandResult r = submit(suite(), out, dir_ / "store",
                                         {"--junit", (dir_ / "cancelled.xml").string(), "--summary",
                                          (dir_ / "cancelled.md").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string gpu = slurmJobId(out, "gpu_array");
    ASSERT_FALSE(gpu.empty());
    ASSERT_EQ(slurm_->command({"scancel", gpu + "_1"}).exit_code, 0);
    EXPECT_EQ(awaitMerge(out), 1);
    const results::RunResults partial = results::readResultsFile(out / "results.json");
    ASSERT_EQ(partial.jobs.size(), 3u);
    EXPECT_THAT(partial.jobs[2].failure, HasSubstr("no result"));
    EXPECT_FALSE(partial.jobs[1].failed());
    const std::string junit = readText(dir_ / "cancelled.xml");
    EXPECT_THAT(junit, HasSubstr("errors=\"1\""));
    EXPECT_THAT(junit, HasSubstr("<error message=\"no result"));
    EXPECT_THAT(readText(dir_ / "cancelled.md"), HasSubstr("1 failed"));

    const test::CommandResult resumed =
        submit(suite(), out, dir_ / "store", {"--resume", "--wait"});
    ASSERT_EQ(resumed.exit_code, 0) << resumed.out << resumed.err;
    EXPECT_THAT(resumed.out, HasSubstr("2 finished earlier"));
    EXPECT_THAT(resumed.out, HasSubstr("technique array (1 tasks)"));
    EXPECT_THAT(resumed.out, Not(HasSubstr("reference array")));
    test::expectSameDeterministicResults(expected, results::readResultsFile(out / "results.json"));
  }

  {
    SCOPED_TRACE("a task that fails: failed in the merged results, with its log");
    const fs::path out = dir_ / "broken";
    const test::CommandResult r =
        submit(suite(), out, dir_ / "store", {"--gl-device", "99", "--wait"});
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    const results::RunResults merged = results::readResultsFile(out / "results.json");
    ASSERT_EQ(merged.jobs.size(), 3u);
    EXPECT_FALSE(merged.jobs[0].failed());
    for (std::size_t i : {1u, 2u}) {
      EXPECT_THAT(merged.jobs[i].failure, HasSubstr("GL device 99"));
      ASSERT_FALSE(merged.jobs[i].outputs.log.empty());
      EXPECT_THAT(readText(out / merged.jobs[i].outputs.log), HasSubstr("GL device 99"));
    }
  }

  {
    SCOPED_TRACE("two suites submitted at once on one new store: each reference rendered once");
    const fs::path store = dir_ / "shared-store";
    ASSERT_EQ(submit(suite(), dir_ / "first", store).exit_code, 0);
    ASSERT_EQ(submit(dir_ / "other.toml", dir_ / "second", store).exit_code, 0);
    EXPECT_EQ(awaitMerge(dir_ / "first"), 0);
    EXPECT_EQ(awaitMerge(dir_ / "second"), 0);
    // Three distinct references, whichever task got each first: the reference job's (all paths,
    // box-filtered) and the technique jobs' pixel-centre ones (LE|LDE; all paths).
    EXPECT_EQ(referencesRendered(dir_ / "first") + referencesRendered(dir_ / "second"), 3);
  }

  SCOPED_TRACE("the merged smoke report in headless Chromium");
  GIB_REQUIRE_CHROMIUM(chromium);
  for (const fs::path& page : smoke_pages) {
    const test::LoadedPage loaded = test::loadPage(*chromium, page, dir_.path());
    EXPECT_EQ(test::reportCheck(loaded.dom), "ok") << page << loaded.log;
    EXPECT_EQ(test::consoleProblems(loaded.log), std::vector<std::string>{}) << page;
  }
}

}  // namespace
}  // namespace gib
