// The timing tests `gibench diff` runs per timed job: the run-to-run test against a history, the
// signed-rank test of interleaved pairs (exact, a dynamic programme over rank sums) and the
// Student t quantiles behind the detectable changes. A nightly diff runs them for hundreds of
// jobs; each must stay far below a millisecond.
#include "metrics/distributions.h"
#include "metrics/timing_statistics.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace {

using namespace gib::metrics;

std::vector<double> times(int n, double median, double phase) {
  std::vector<double> out;
  for (int i = 0; i < n; ++i) out.push_back(median * (1.0 + 0.1 * std::sin(phase + 1.7 * i)));
  return out;
}

void BM_RunToRunSpreadTest(benchmark::State& state) {
  const std::vector<double> history = times(int(state.range(0)), 10.0, 0.3);
  for (auto _ : state)
    benchmark::DoNotOptimize(testAgainstRunToRunSpread(10.0, 11.0, history, 0.0025));
}
BENCHMARK(BM_RunToRunSpreadTest)->Arg(30)->Unit(benchmark::kMicrosecond);

void BM_InterleavedPairsTest(benchmark::State& state) {
  const int pairs = int(state.range(0));
  const std::vector<double> a = times(pairs, 10.0, 0.1), b = times(pairs, 12.5, 0.4);
  for (auto _ : state) benchmark::DoNotOptimize(testInterleavedPairs(a, b, 0.0025));
}
BENCHMARK(BM_InterleavedPairsTest)->Arg(16)->Arg(100)->Unit(benchmark::kMicrosecond);

void BM_StudentTQuantile(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(studentTQuantile(0.99875, 7.0));
}
BENCHMARK(BM_StudentTQuantile)->Unit(benchmark::kMicrosecond);

}  // namespace
