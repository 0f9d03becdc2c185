// `gibench run` end to end on a tiny suite: results, store reuse, resume after an interruption,
// and the bad inputs that must stop a run before it writes anything.
#include "support/run_command.h"
#include "results/results.h"
#include "results/results_json.h"
#include "support/read_text.h"
#include "support/temp_dir.h"
#include "support/tiny_suite.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <thread>
#include <utility>
#include <vector>

extern char** environ;

namespace gib {
namespace {

namespace fs = std::filesystem;
using test::readText;
using ::testing::HasSubstr;
using ::testing::Not;

void writeFile(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

class RunCommandTest : public ::testing::Test {
 protected:
  RunCommandTest() { writeFile(suite(), test::kTinySuite); }

  fs::path suite() const { return dir_ / "tiny.toml"; }
  fs::path store() const { return dir_ / "store"; }

  test::CommandResult run(const fs::path& out, std::vector<std::string> more = {}) const {
    std::vector<std::string> args = {"run",        suite().string(), "--out",
                                     out.string(), "--store",        store().string()};
    args.insert(args.end(), more.begin(), more.end());
    return test::runGibench(args, dir_.path());
  }

  test::TempDir dir_;
};

TEST_F(RunCommandTest, WritesResultsCsvHistoryAndReport) {
  const fs::path out = dir_ / "run1";
  const test::CommandResult r = run(out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const results::RunResults results = results::readResultsFile(out / "results.json");
  ASSERT_EQ(results.jobs.size(), 3u);
  EXPECT_EQ(results.run.suite, "tiny");
  EXPECT_TRUE(results.run.complete);
  EXPECT_EQ(results.primary_metric, "relmse");
  EXPECT_EQ(results.tolerances.forMetric("relmse").relative, 0.1);
  ASSERT_EQ(results.paper.size(), 1u);

  const results::JobResult& reference = results.jobs[0];
  EXPECT_EQ(reference.id, "cornell-reference");
  ASSERT_TRUE(reference.convergence.has_value());
  ASSERT_EQ(reference.convergence->points.size(), 3u);
  // The fit follows the index's metric (relMSE).
  EXPECT_EQ(reference.convergence->fit_metric, "relmse");
  // The expected relMSE of an independent render falls as 1/spp (a slope of −1 on log-log axes)
  // while the reference's own variance is negligible; three points of a 1024-pixel image scatter
  // about that, hence the wide bounds.
  EXPECT_LT(reference.convergence->fit_slope, -0.6);
  EXPECT_GT(reference.convergence->fit_slope, -1.5);
  EXPECT_FALSE(reference.reference.store_hit);
  // The reference's own job keeps the box filter; its page links the reference it measured.
  EXPECT_EQ(reference.reference.pixel_sampling, "area");
  EXPECT_TRUE(fs::is_regular_file(out / reference.outputs.reference_exr));

  for (const std::size_t i : {1u, 2u}) {
    const results::JobResult& direct = results.jobs[i];
    EXPECT_EQ(direct.technique, "direct");
    EXPECT_EQ(direct.path_class, "L(D|S|P){0,1}E");
    EXPECT_EQ(direct.reference.path_class, "L(D|S|P){0,1}E");
    ASSERT_TRUE(direct.full_reference.has_value());
    // Technique jobs are measured against pixel-centre references, the class's and the full
    // one, keyed apart from the reference job's box-filtered one: the full one is rendered by
    // the first technique job and found in the store by the second.
    EXPECT_EQ(direct.reference.pixel_sampling, "center");
    EXPECT_EQ(direct.full_reference->pixel_sampling, "center");
    EXPECT_NE(direct.full_reference->key, results.jobs[0].reference.key);
    EXPECT_EQ(direct.full_reference->store_hit, i == 2);
    // The pixels whose primary hit rasteriser and ray tracer disagree on: counted (the Cornell
    // box's silhouettes at 32² are a few pixels, under 3 %), and shown.
    EXPECT_GE(direct.disagreement_pixels, 0);
    EXPECT_LT(direct.disagreement_pixels, 32 * 32 * 3 / 100);
    EXPECT_TRUE(fs::is_regular_file(out / direct.outputs.disagreement_png));
    ASSERT_TRUE(direct.metric("relmse").has_value());
    EXPECT_TRUE(direct.frameMedianMs().has_value());
    // Direct light leaves out indirect light: farther from the full reference than its own.
    // (relMSE, not MSE: MSE is dominated by the bright emitter's edge pixels at this size.)
    auto relmse = [](const results::NamedValues& values) {
      for (const auto& [name, value] : values)
        if (name == "relmse") return value;
      return -1.0;
    };
    EXPECT_GT(relmse(direct.metrics_full), 2 * relmse(direct.metrics));
    // Its class reference is another store entry than the reference job's full one.
    EXPECT_NE(direct.reference.key, reference.reference.key);
    for (const std::string& file :
         {direct.outputs.image, direct.outputs.image_png, direct.outputs.reference_png,
          direct.outputs.difference_png, direct.outputs.flip_png, direct.outputs.timings_json,
          direct.outputs.reference_exr, direct.outputs.full_reference_exr})
      EXPECT_TRUE(fs::is_regular_file(out / file)) << file;
  }
  EXPECT_EQ(results.jobs[1].id, "cornell-direct/shadow=hard");
  EXPECT_EQ(results.jobs[2].id, "cornell-direct/shadow=pcf");
  EXPECT_TRUE(fs::is_regular_file(out / "index.html"));
  // The suite's [[figure]]: recorded, with its page and its panels in one picture (three 32×32
  // images in a row).
  ASSERT_EQ(results.figures.size(), 1u);
  EXPECT_EQ(results.figures[0].panels.size(), 3u);
  EXPECT_TRUE(fs::is_regular_file(out / "report" / "figure-shadows.html"));
  EXPECT_TRUE(fs::is_regular_file(out / "figures" / "shadows.png"));
  EXPECT_EQ(test::countLines(readText(out / "results.csv")), 4);  // header + 3 jobs
  EXPECT_TRUE(fs::is_regular_file(store() / "history.sqlite"));
  EXPECT_THAT(r.out, HasSubstr("report     "));
  EXPECT_THAT(r.err, HasSubstr("[3/3] cornell-direct/shadow=pcf: done"));
}

// A GL driver that rejects the technique's shaders (injected: realtime/gl/fault_injection.h) fails
// its jobs, not the run: the reference job is measured, the report shows the failed jobs, the
// command ends with one line and exit code 1, no history row is written, and a resume without
// the fault completes the run.
TEST_F(RunCommandTest, JobsTheGlDriverCannotRunAreReportedAndTheOthersRun) {
  const fs::path out = dir_ / "faulty";
  const std::vector<std::string> args = {
      "run",     suite().string(), "--out", out.string(),
      "--store", store().string(), "--db",  (dir_ / "h.sqlite").string()};
  const test::CommandResult r =
      test::runGibench(args, dir_.path(), {"GIB_GL_FAULT=shader-compile"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  std::string error_lines;
  for (std::size_t at = r.err.find("gibench: "); at != std::string::npos;
       at = r.err.find("gibench: ", at + 1))
    error_lines += r.err.substr(at, r.err.find('\n', at) - at) + "\n";
  EXPECT_EQ(test::countLines(error_lines), 1) << r.err;
  EXPECT_THAT(error_lines,
              HasSubstr("gibench: 2 of 3 jobs failed (first, cornell-direct/shadow=hard: "
                        "technique 'direct': "));
  EXPECT_THAT(error_lines, HasSubstr("does not compile"));

  const results::RunResults results = results::readResultsFile(out / "results.json");
  ASSERT_EQ(results.jobs.size(), 3u);
  EXPECT_FALSE(results.jobs[0].failed());
  EXPECT_TRUE(results.jobs[0].convergence.has_value());
  for (const std::size_t i : {1u, 2u}) {
    EXPECT_THAT(results.jobs[i].failure, HasSubstr("technique 'direct': "));
    EXPECT_THAT(results.jobs[i].failure, Not(HasSubstr("\n")));
  }
  // The index marks the failed jobs; each job's page gives the cause.
  EXPECT_NE(readText(out / "index.html").find("<div class=\"failure\">failed</div>"),
            std::string::npos);
  EXPECT_NE(readText(out / "report" / "cornell-direct__shadow-hard.html").find("does not compile"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "h.sqlite") &&
               test::runGibench({"history", "--db", (dir_ / "h.sqlite").string()}, dir_.path())
                       .out.find("tiny") != std::string::npos);

  const test::CommandResult resumed = test::runGibench(args, dir_.path());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_THAT(resumed.err, HasSubstr("cornell-reference: finished by an earlier attempt"));
  for (const results::JobResult& job : results::readResultsFile(out / "results.json").jobs)
    EXPECT_FALSE(job.failed()) << job.id;
}

TEST_F(RunCommandTest, ALaterRunReusesTheStoredReferences) {
  ASSERT_EQ(run(dir_ / "first").exit_code, 0);
  const test::CommandResult r = run(dir_ / "second");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const results::RunResults first = results::readResultsFile(dir_ / "first");
  const results::RunResults second = results::readResultsFile(dir_ / "second");
  EXPECT_NE(first.run.id, second.run.id);
  for (std::size_t i = 0; i < second.jobs.size(); ++i) {
    EXPECT_TRUE(second.jobs[i].reference.store_hit) << second.jobs[i].id;
    // Same inputs, same references, same measurements.
    EXPECT_EQ(second.jobs[i].metrics, first.jobs[i].metrics) << second.jobs[i].id;
  }
  EXPECT_THAT(r.err, Not(HasSubstr("rendered in")));
}

TEST_F(RunCommandTest, ParallelJobsMeasureTheSame) {
  ASSERT_EQ(run(dir_ / "serial").exit_code, 0);
  const test::CommandResult r = run(dir_ / "parallel", {"--jobs", "2"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const results::RunResults serial = results::readResultsFile(dir_ / "serial");
  const results::RunResults parallel = results::readResultsFile(dir_ / "parallel");
  ASSERT_EQ(parallel.jobs.size(), serial.jobs.size());
  for (std::size_t i = 0; i < serial.jobs.size(); ++i)
    EXPECT_EQ(parallel.jobs[i].metrics, serial.jobs[i].metrics) << serial.jobs[i].id;
  EXPECT_EQ(parallel.run.parallel_jobs, 2);
}

// Starts gibench, kills it (SIGKILL: no chance to tidy up) as soon as the first job has recorded
// its result, and checks that a rerun with the same --out finishes the run, skipping that job.
TEST_F(RunCommandTest, AnInterruptedRunIsResumed) {
  const fs::path out = dir_ / "interrupted";
  const std::vector<std::string> args = {GIB_GIBENCH_PATH, "run",     suite().string(), "--out",
                                         out.string(),     "--store", store().string()};
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const std::string log = (dir_ / "interrupted.log").string();
  posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  const fs::path first_result = out / "jobs" / "cornell-reference" / "result.json";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!fs::exists(first_result) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(fs::exists(first_result)) << readText(log);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it could be interrupted";
  EXPECT_FALSE(fs::exists(out / "results.json"));
  const results::JobResult recorded = results::readJobFile(first_result);

  const test::CommandResult r = run(out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("resuming run"));
  EXPECT_THAT(r.err, HasSubstr("cornell-reference: finished by an earlier attempt, skipped"));
  EXPECT_THAT(r.out, HasSubstr("2 run, 1 finished earlier"));
  const results::RunResults results = results::readResultsFile(out);
  ASSERT_EQ(results.jobs.size(), 3u);
  EXPECT_EQ(results.jobs[0], recorded);
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(out))
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos)
        << "left behind: " << entry.path();
}

TEST_F(RunCommandTest, ARerunOfAFinishedRunRunsNothing) {
  const fs::path out = dir_ / "done";
  ASSERT_EQ(run(out).exit_code, 0);
  const results::RunResults before = results::readResultsFile(out);
  const test::CommandResult r = run(out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("0 run, 3 finished earlier"));
  const results::RunResults after = results::readResultsFile(out);
  EXPECT_EQ(after.run.id, before.run.id);
  EXPECT_EQ(after.jobs, before.jobs);
}

TEST_F(RunCommandTest, OnlyAndListSelectJobs) {
  const test::CommandResult list =
      test::runGibench({"run", suite().string(), "--list", "--only", "*/shadow=pcf"}, dir_.path());
  ASSERT_EQ(list.exit_code, 0) << list.err;
  EXPECT_EQ(list.out, "cornell-direct/shadow=pcf\n");
  const fs::path out = dir_ / "subset";
  const test::CommandResult r = run(out, {"--only", "cornell-direct/*"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const results::RunResults results = results::readResultsFile(out);
  ASSERT_EQ(results.jobs.size(), 2u);
  EXPECT_FALSE(results.run.complete);
}

TEST_F(RunCommandTest, BadInputStopsBeforeAnythingIsWritten) {
  auto expectRefused = [&](const std::vector<std::string>& more, const std::string& message,
                           const fs::path& out) {
    const test::CommandResult r = run(out, more);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_THAT(r.err, HasSubstr(message));
    EXPECT_EQ(test::countLines(r.err), 1) << r.err;
    EXPECT_FALSE(fs::exists(out / "run-state.json")) << out;
  };
  expectRefused({"--jobs", "0"}, "--jobs 0 runs nothing", dir_ / "a");
  expectRefused({"--only", "nothing*"}, "--only 'nothing*' matches no job", dir_ / "b");
  writeFile(dir_ / "file", "x");
  expectRefused({}, "is a file; give a directory", dir_ / "file");
  fs::create_directories(dir_ / "busy");
  writeFile(dir_ / "busy" / "notes.txt", "mine");
  expectRefused({}, "is not empty and holds no gibench run", dir_ / "busy");

  writeFile(suite(), std::string(test::kTinySuite) + R"(
[[case]]
name = "bad"
scene = "cornell"
technique = "direct"
checkpoints = [1, 2]
)");
  expectRefused({}, "checkpoints are iteration counts of an iterative technique", dir_ / "c");
  writeFile(suite(), std::string(test::kTinySuite) + R"(
[[case]]
name = "bad"
scene = "cornell"
technique = "direct"
iterations = 5
)");
  expectRefused({}, "renders in one step and takes no iterations", dir_ / "d");

  const test::CommandResult missing =
      test::runGibench({"run", (dir_ / "nope.toml").string()}, dir_.path());
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_THAT(missing.err, HasSubstr("suite file not found"));
}

TEST_F(RunCommandTest, ARunDirectoryBelongsToOneSuite) {
  const fs::path out = dir_ / "mine";
  ASSERT_EQ(run(out, {"--only", "cornell-reference"}).exit_code, 0);
  writeFile(suite(), std::string(test::kTinySuite).replace(0, 13, "name = \"other\""));
  const test::CommandResult r = run(out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("holds a run of suite 'tiny', not 'other'"));
}

TEST_F(RunCommandTest, ListSuitesShowsTheShippedOnes) {
  const test::CommandResult r = test::runGibench({"list", "suites"}, dir_.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("suites/smoke.toml"));
  EXPECT_THAT(r.out, HasSubstr("suites/nightly.toml"));
}

}  // namespace
}  // namespace gib

namespace gib {
namespace {

// `repeats`: each technique job timed that many times with a fresh context, every repeat kept,
// the job's timings the repeat of the median; reference jobs run once; the machine's conditions
// recorded for the run and each job.
TEST_F(RunCommandTest, RepeatsTimeEachTechniqueJobSeveralTimes) {
  std::string suite_text = test::kTinySuite;
  suite_text.replace(suite_text.find("warmup = 0"), 10, "warmup = 0\nrepeats = 3");
  writeFile(suite(), suite_text);
  const fs::path out = dir_ / "out";
  const test::CommandResult r = run(out, {"--no-history"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("(run 3/3): timing again"));
  const results::RunResults results = results::readResultsFile(out);
  EXPECT_GE(results.run.conditions.load_before, 0.0);
  EXPECT_GE(results.run.conditions.other_gibench, 0);
  for (const results::JobResult& job : results.jobs) {
    EXPECT_GE(job.conditions.load_after, 0.0) << job.id;
    if (job.technique == "reference") {
      EXPECT_TRUE(job.repeats.empty());
      continue;
    }
    ASSERT_EQ(job.repeats.size(), 3u) << job.id;
    const std::vector<double> medians = job.repeatMediansMs();
    ASSERT_EQ(medians.size(), 3u);
    std::vector<double> sorted = medians;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(job.frameMedianMs(), sorted[1]);  // the repeat of the median is the one shown
    EXPECT_EQ(*job.runMedianMs(), sorted[1]);
  }
  // Repeats are part of what defines a job: a resume with another count runs them again.
  writeFile(suite(), test::kTinySuite);
  EXPECT_THAT(run(out, {"--no-history"}).err, Not(HasSubstr("finished by an earlier attempt")));
}

TEST_F(RunCommandTest, RepeatsOutOfRangeAreRefused) {
  std::string suite_text = test::kTinySuite;
  suite_text.replace(suite_text.find("warmup = 0"), 10, "warmup = 0\nrepeats = 0");
  writeFile(suite(), suite_text);
  const test::CommandResult r = run(dir_ / "out");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("repeats"));
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

// An executable shell script (a stand-in for another build of gibench).
fs::path writeScript(const fs::path& path, const std::string& body) {
  writeFile(path, "#!/bin/sh\n" + body);
  fs::permissions(path, fs::perms::owner_exec, fs::perm_options::add);
  return path;
}

// `gibench diff --confirm` between two runs of one build, given as two builds that mark in a log
// which of them rendered: with no history (--no-history) nothing settles a timing before the A/B
// runs, so each timed job is rendered A B A B … and its verdict rests on those pairs; a build
// that cannot be found is named as the fix.
TEST_F(RunCommandTest, DiffConfirmRendersEachBuildAlternately) {
  ASSERT_EQ(run(dir_ / "a", {"--no-history"}).exit_code, 0);
  ASSERT_EQ(run(dir_ / "b", {"--no-history"}).exit_code, 0);
  const fs::path order = dir_ / "order.log";
  auto marking = [&](const std::string& mark) {
    return writeScript(dir_ / ("gibench-" + mark), "printf " + mark + " >>'" + order.string() +
                                                       "'\nexec '" GIB_GIBENCH_PATH "' \"$@\"\n")
        .string();
  };
  constexpr int kPairs = 3;
  const test::CommandResult r =
      test::runGibench({"diff", (dir_ / "a").string(), (dir_ / "b").string(), "--confirm",
                        "--pairs", std::to_string(kPairs), "--base-gibench", marking("A"),
                        "--new-gibench", marking("B"), "--json", "--store", store().string()},
                       dir_.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, Not(HasSubstr("could not confirm")));
  const nlohmann::json diff = nlohmann::json::parse(r.out);
  ASSERT_EQ(diff["timings"].size(), 2u);
  for (const auto& timing : diff["timings"]) {
    EXPECT_EQ(timing["evidence"], "interleaved A/B") << timing["job"];
    EXPECT_EQ(timing["pairs_base_ms"].size(), std::size_t(kPairs)) << timing["job"];
    EXPECT_EQ(timing["pairs_new_ms"].size(), std::size_t(kPairs)) << timing["job"];
  }
  // Job after job, each pair the base build's render then the new build's.
  std::string alternating;
  for (std::size_t i = 0; i < std::size_t(kPairs) * diff["timings"].size(); ++i)
    alternating += "AB";
  EXPECT_EQ(readText(order), alternating);

  const test::CommandResult missing =
      test::runGibench({"diff", (dir_ / "a").string(), (dir_ / "b").string(), "--confirm",
                        "--base-gibench", (dir_ / "nowhere").string(), "--store", store().string()},
                       dir_.path());
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_THAT(missing.err, HasSubstr("--base-gibench"));
  EXPECT_EQ(test::countLines(missing.err), 1) << missing.err;
}

// A build that cannot render the jobs (a base build lacking their technique, say): each timing
// keeps the runs' own verdict, named on stderr, and the diff exits 4, not 0, since it cannot say
// the timings are unchanged (a bisect step skips such a commit); a regression found otherwise
// still exits 1.
TEST_F(RunCommandTest, DiffConfirmThatCannotRenderExitsFour) {
  ASSERT_EQ(run(dir_ / "a", {"--no-history"}).exit_code, 0);
  const std::string broken =
      writeScript(dir_ / "broken-gibench", "echo 'no such technique' >&2\nexit 2\n").string();
  const std::string a = (dir_ / "a").string();
  const test::CommandResult r =
      test::runGibench({"diff", a, a, "--confirm", "--pairs", "2", "--base-gibench", broken,
                        "--json", "--store", store().string()},
                       dir_.path());
  EXPECT_EQ(r.exit_code, 4) << r.err;
  for (const char* job : {"cornell-direct/shadow=hard", "cornell-direct/shadow=pcf"})
    EXPECT_THAT(r.err, HasSubstr(std::string("gibench: could not confirm ") + job + ": "));
  EXPECT_THAT(r.err, HasSubstr("no such technique"));
  const nlohmann::json diff = nlohmann::json::parse(r.out);
  ASSERT_EQ(diff["timings"].size(), 2u);
  for (const auto& timing : diff["timings"])
    EXPECT_EQ(timing["evidence"], "frames") << timing["job"];

  results::RunResults worse = results::readResultsFile(dir_ / "a");
  for (auto& [name, value] : worse.jobs[1].metrics)
    if (name == "relmse") value *= 2;
  results::writeResultsFile(dir_ / "worse.json", worse);
  EXPECT_EQ(test::runGibench({"diff", a, (dir_ / "worse.json").string(), "--confirm", "--pairs",
                              "2", "--base-gibench", broken, "--store", store().string()},
                             dir_.path())
                .exit_code,
            1);
}

// Options `diff` cannot act on: a pair count no test can use, and A/B options without --confirm
// (which would otherwise be ignored without a word). One line each, exit 2, naming the option.
TEST_F(RunCommandTest, DiffRefusesOptionsItCannotActOn) {
  ASSERT_EQ(run(dir_ / "a", {"--no-history"}).exit_code, 0);
  const std::string a = (dir_ / "a").string();
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--confirm", "--pairs", "1"}, "--pairs"},
      {{"--confirm", "--pairs", "101"}, "--pairs"},
      {{"--pairs", "16"}, "--confirm"},
      {{"--base-gibench", "gibench"}, "--confirm"},
      {{"--history-runs", "0"}, "--history-runs"},
  };
  for (const auto& [options, named] : cases) {
    std::vector<std::string> args = {"diff", a, a, "--store", store().string()};
    args.insert(args.end(), options.begin(), options.end());
    const test::CommandResult r = test::runGibench(args, dir_.path());
    EXPECT_EQ(r.exit_code, 2) << options.back() << ": " << r.err;
    EXPECT_THAT(r.err, HasSubstr(named));
    EXPECT_EQ(test::countLines(r.err), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

}  // namespace
}  // namespace gib
