// The harness's own costs, apart from the rendering it drives: reading and expanding a suite,
// checking every job before a run starts (scenes loaded, parameters parsed, job hashes), and a
// whole run of a small suite whose references are already in the store (what every nightly job
// pays beyond its frames: context creation, metrics, images, results, history, report).
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
// from a warm store, into a fresh run directory each time.
void BM_SmallRunWarmStore(benchmark::State& state) {
  const bench::TemporaryDirectory temporary("gib-bench-run");
  const fs::path& root = temporary.path();
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
  const Suite suite = loadSuiteFile(root / "small.toml");
  RunOptions options;
  options.store_root = root / "store";
  options.history_db = root / "store" / "history.sqlite";
  options.log = std::fopen("/dev/null", "w");
  int run = 0;
  options.out_dir = root / "warm-up";
  runSuite(suite, options);  // fills the store
  for (auto _ : state) {
    options.out_dir = root / ("run" + std::to_string(run++));
    benchmark::DoNotOptimize(runSuite(suite, options));
  }
  std::fclose(options.log);
}
BENCHMARK(BM_SmallRunWarmStore)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
}  // namespace gib::suites
