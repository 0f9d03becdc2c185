// The harness's bookkeeping must stay negligible beside rendering: a nightly run has about a
// thousand jobs, and `gibench diff` inside `git bisect run` reads and compares two of them per
// step; every run is appended to the history database.
#include <benchmark/benchmark.h>
#include <stdlib.h>

#include <cstdint>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>

#include "results/history_db.h"
#include "results/results_diff.h"
#include "results/results_json.h"
#include "results/timing_history.h"
#include "support/synthetic_timings.h"
#include "support/temporary_directory.h"

namespace gib::results {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

constexpr int kFrames = 16;

// A run of `job_count` technique jobs with five metric values and 16 noisy frame times each:
// the shape of a nightly run, so parsing and comparing see realistic sizes.
RunResults makeRun(const std::string& id, int job_count, std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  std::lognormal_distribution<double> noise(0.0, 0.03);
  RunResults run;
  run.run.id = id;
  run.run.suite = "nightly";
  run.run.started = "2026-11-22T02:00:00Z";
  run.run.git_commit = "0123456789abcdef0123456789abcdef01234567";
  run.primary_metric = "relmse";
  for (int i = 0; i < job_count; ++i) {
    JobResult job;
    job.id = "scene" + std::to_string(i % 4) + "-technique/k=" + std::to_string(i);
    job.slug = job.id;
    job.scene = "scene" + std::to_string(i % 4);
    job.technique = "technique";
    job.parameters = {{"k", std::to_string(i)}, {"mode", "fast"}};
    job.width = 256;
    job.height = 256;
    job.reference.key = "key-" + std::to_string(i % 8);
    for (const char* metric : {"relmse", "mae", "psnr", "ssim", "flip_mean"})
      job.metrics.emplace_back(metric, 0.01 * noise(generator));
    std::vector<double> frames;
    for (int f = 0; f < kFrames; ++f) frames.push_back(5.0 * noise(generator));
    job.timings = test::frameTimings(frames);
    run.jobs.push_back(std::move(job));
  }
  return run;
}

void BM_DiffResults(benchmark::State& state) {
  const int jobs = int(state.range(0));
  const RunResults base = makeRun("base", jobs, 1);
  const RunResults next = makeRun("next", jobs, 2);
  for (auto _ : state) {
    DiffReport diff = diffResults(base, next);
    benchmark::DoNotOptimize(diff.metrics.data());
  }
  state.SetItemsProcessed(state.iterations() * jobs);  // jobs compared per second
}
BENCHMARK(BM_DiffResults)->Arg(1000)->Unit(benchmark::kMillisecond);

// From a parsed document (the strict field checks and the copy into RunResults).
void BM_ResultsFromJson(benchmark::State& state) {
  const int jobs = int(state.range(0));
  const json document = resultsToJson(makeRun("run", jobs, 1));
  for (auto _ : state) {
    RunResults results = resultsFromJson(document, "bench");
    benchmark::DoNotOptimize(results.jobs.data());
  }
  state.SetItemsProcessed(state.iterations() * jobs);
}
BENCHMARK(BM_ResultsFromJson)->Arg(1000)->Unit(benchmark::kMillisecond);

// From the file's text, as `gibench diff` reads it: JSON parsing included.
void BM_ParseAndReadResults(benchmark::State& state) {
  const int jobs = int(state.range(0));
  const std::string text = resultsToJson(makeRun("run", jobs, 1)).dump(2);
  for (auto _ : state) {
    RunResults results = resultsFromJson(json::parse(text), "bench");
    benchmark::DoNotOptimize(results.jobs.data());
  }
  state.SetBytesProcessed(state.iterations() * std::int64_t(text.size()));
}
BENCHMARK(BM_ParseAndReadResults)->Arg(1000)->Unit(benchmark::kMillisecond);

// A diff judged against a history: per job, its comparable earlier runs found among 20 recorded
// runs of the suite (timingHistoryOf) and the run-to-run test, as `gibench diff` and the report do
// for a nightly run.
void BM_DiffResultsWithHistory(benchmark::State& state) {
  const int jobs = int(state.range(0));
  std::vector<RunResults> history;
  for (int i = 0; i < 20; ++i) {
    history.push_back(makeRun("history-" + std::to_string(i), jobs, std::uint64_t(10 + i)));
    history.back().run.started = "2026-11-" + std::to_string(10 + i) + "T02:00:00Z";
  }
  const RunResults base = makeRun("base", jobs, 1);
  RunResults next = makeRun("next", jobs, 2);
  next.run.started = "2026-11-30T02:00:00Z";
  for (auto _ : state) {
    DiffOptions options;
    options.history = timingHistoryOf(history, base, next);
    DiffReport diff = diffResults(base, next, options);
    benchmark::DoNotOptimize(diff.timings.data());
  }
  state.SetItemsProcessed(state.iterations() * jobs);
}
BENCHMARK(BM_DiffResultsWithHistory)->Arg(1000)->Unit(benchmark::kMillisecond);

// Reading that history from the database: the 20 runs of 1000 jobs, parsed back.
void BM_LoadTimingHistory(benchmark::State& state) {
  const int jobs = int(state.range(0));
  const bench::TemporaryDirectory temporary("gib_timing_history_bench");
  HistoryDatabase db = HistoryDatabase::open(temporary.path() / "history.sqlite");
  for (int i = 0; i < 20; ++i) {
    RunResults run = makeRun("history-" + std::to_string(i), jobs, std::uint64_t(10 + i));
    run.run.started = "2026-11-" + std::to_string(10 + i) + "T02:00:00Z";
    db.append(run);
  }
  const RunResults base = makeRun("base", jobs, 1);
  RunResults next = makeRun("next", jobs, 2);
  next.run.started = "2026-11-30T02:00:00Z";
  for (auto _ : state) {
    TimingHistory history = loadTimingHistory(db, base, next, 20);
    benchmark::DoNotOptimize(history.size());
  }
  state.SetItemsProcessed(state.iterations() * jobs);
}
BENCHMARK(BM_LoadTimingHistory)->Arg(1000)->Unit(benchmark::kMillisecond)->UseRealTime();

// One append of a new run (a transaction with its jobs and metric values, committed to disk) to
// a database in a temporary directory.
void BM_HistoryAppend(benchmark::State& state) {
  const int jobs = int(state.range(0));
  const bench::TemporaryDirectory temporary("gib_history_bench");
  // Declared after the directory, so closed before the directory is removed.
  HistoryDatabase db = HistoryDatabase::open(temporary.path() / "history.sqlite");
  RunResults run = makeRun("run", jobs, 1);
  std::int64_t count = 0;
  for (auto _ : state) {
    run.run.id = "run-" + std::to_string(count++);
    benchmark::DoNotOptimize(db.append(run));
  }
  state.SetItemsProcessed(state.iterations() * jobs);
}
// Real time: the commit waits for the disk, which CPU time would not count.
BENCHMARK(BM_HistoryAppend)->Arg(100)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace gib::results
