// The harness's own costs, apart from the rendering it drives: reading and expanding a suite,
// checking every job before a run starts (scenes loaded, parameters parsed, job hashes), and a
// whole run of a small suite whose references are already in the store (what every nightly job
// pays beyond its frames: context creation, metrics, images, results, history, report), and the
// same run split into shards and merged.
#include "results/results_json.h"
#include "suites/job_execution.h"
#include "suites/suite_file.h"
#include "suites/suite_runner.h"
#include "support/temporary_directory.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace gib::suites {
namespace {

namespace fs = std::filesystem;

const fs::path kNightly = fs::path(GIB_SOURCE_DIR) / "suites" / "nightly.toml";

void BM_LoadAndExpandNightly(benchmark::State& state) {
  for (auto _ : state) {
    const Suite suite = loadSuiteFile(kNightly);
    benchmark::DoNotOptimize(expandSuite(suite));
  }
}
BENCHMARK(BM_LoadAndExpandNightly)->Unit(benchmark::kMillisecond);

void BM_PrepareNightlyJobs(benchmark::State& state) {
  const std::vector<Job> jobs = expandSuite(loadSuiteFile(kNightly));
  for (auto _ : state)
    for (const Job& job : jobs) benchmark::DoNotOptimize(prepareJob(job));
  state.counters["jobs"] = double(jobs.size());
}
BENCHMARK(BM_PrepareNightlyJobs)->Unit(benchmark::kMillisecond);

// Three jobs (a reference with a convergence series and two `direct` jobs) at 32x32, references
// from a warm store: the suite, options into `root` and the warm-up run that fills the store.
struct SmallRun {
  explicit SmallRun(const fs::path& root) {
    std::ofstream(root / "small.toml") << R"(name = "small"
[defaults]
width = 32
height = 32
metrics = ["relmse", "flip"]
frames = 4
warmup = 1
[defaults.reference]
spp = 64
[[case]]
scene = "cornell"
technique = "reference"
checkpoints = [4, 16]
[[case]]
scene = "cornell"
technique = "direct"
set = { shadow = ["hard", "pcf"], light_samples = 4 }
)";
    suite = loadSuiteFile(root / "small.toml");
    options.store_root = root / "store";
    options.history_db = root / "store" / "history.sqlite";
    options.log = std::fopen("/dev/null", "w");
    options.out_dir = root / "warm-up";
    runSuite(suite, options);  // fills the store
  }
  ~SmallRun() { std::fclose(options.log); }
  Suite suite;
  RunOptions options;
};

// A whole run into a fresh run directory each time.
void BM_SmallRunWarmStore(benchmark::State& state) {
  const bench::TemporaryDirectory temporary("gib-bench-run");
  SmallRun small(temporary.path());
  int run = 0;
  for (auto _ : state) {
    small.options.out_dir = temporary.path() / ("run" + std::to_string(run++));
    benchmark::DoNotOptimize(runSuite(small.suite, small.options));
  }
}
BENCHMARK(BM_SmallRunWarmStore)->Unit(benchmark::kMillisecond)->Iterations(3);

// The same run as `--shard 1/2` and `--shard 2/2` into one directory, then `gibench merge`: what
// splitting a run costs beside BM_SmallRunWarmStore (a second process start is not included).
void BM_SmallRunShardedAndMerged(benchmark::State& state) {
  const bench::TemporaryDirectory temporary("gib-bench-shards");
  SmallRun small(temporary.path());
  int run = 0;
  for (auto _ : state) {
    RunOptions part = small.options;
    part.out_dir = temporary.path() / ("run" + std::to_string(run++));
    part.part = true;
    part.shard.count = 2;
    for (int index : {1, 2}) {
      part.shard.index = index;
      runSuite(small.suite, part);
    }
    RunOptions merge = small.options;
    merge.out_dir.clear();
    benchmark::DoNotOptimize(mergeRuns({part.out_dir}, merge));
  }
}
BENCHMARK(BM_SmallRunShardedAndMerged)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
}  // namespace gib::suites
