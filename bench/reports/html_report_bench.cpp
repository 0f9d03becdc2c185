// The HTML report of a nightly-sized run (50 technique jobs with nested pass timings and
// convergence, coloured against a previous run, trends over 20 runs), and each SVG chart alone.
#include "reports/html_report.h"
#include "reports/svg_charts.h"
#include "support/synthetic_report_run.h"
#include "support/temporary_directory.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace {

using namespace gib;
namespace fs = std::filesystem;

constexpr int kJobs = 50;
constexpr int kTrendRuns = 20;

results::RunResults nightlyRun(const std::string& id, double drift) {
  results::RunResults run = test::syntheticReportResults(id);
  run.jobs.clear();
  run.paper.clear();
  for (int i = 0; i < kJobs; ++i)
    run.jobs.push_back(test::syntheticTechniqueJob("light_samples=" + std::to_string(i + 1),
                                                   0.002 * (1 + drift) / (i + 1), 1 + 0.01 * i));
  return run;
}

// A run directory with its pictures, made once; the timed loop writes the report into it.
struct ReportFixture {
  const bench::TemporaryDirectory temporary{"gib-report-bench"};
  const fs::path& dir = temporary.path();
  results::RunResults results = nightlyRun("20261122-100405-nightly-1a2b3c4d", 0);
  reports::ReportContext context;
  ReportFixture() {
    test::writeSyntheticOutputs(dir, results);
    context.previous = nightlyRun("20261121-100405-nightly-00000000", 0.2);
    for (int r = 0; r < kTrendRuns; ++r)
      context.history.push_back(nightlyRun("run-" + std::to_string(r), 0.01 * r));
  }
};

void BM_WriteHtmlReport50Jobs(benchmark::State& state) {
  static ReportFixture fixture;
  for (auto _ : state)
    benchmark::DoNotOptimize(writeHtmlReport(fixture.dir, fixture.results, fixture.context));
  // Pages written: one per job and the index.
  state.SetItemsProcessed(std::int64_t(state.iterations()) * (kJobs + 1));
}
BENCHMARK(BM_WriteHtmlReport50Jobs)->Unit(benchmark::kMillisecond);

void BM_PassTimingChart(benchmark::State& state) {
  const std::vector<reports::PassBar> passes = {{"frame", 0, 20, 19, 21},
                                                {"gbuffer", 1, 3, 2.9, 3.1},
                                                {"shadow_maps", 1, 6, 5.7, 6.3},
                                                {"cube_faces", 2, 5, 4.8, 5.2},
                                                {"shading", 1, 10, 9.5, 10.5}};
  for (auto _ : state) benchmark::DoNotOptimize(reports::passTimingChart(passes));
}
BENCHMARK(BM_PassTimingChart)->Unit(benchmark::kMicrosecond);

void BM_ConvergenceChart(benchmark::State& state) {
  reports::LogLogPlot plot{
      "Convergence of relmse", "spp", "relmse", {}, reports::FittedSlope{-0.98, 0.03}};
  for (int i = 0; i < 12; ++i) plot.points.emplace_back(std::pow(2.0, i), 0.5 / std::pow(2.0, i));
  for (auto _ : state) benchmark::DoNotOptimize(reports::logLogChart(plot));
}
BENCHMARK(BM_ConvergenceChart)->Unit(benchmark::kMicrosecond);

void BM_TrendChart(benchmark::State& state) {
  std::vector<reports::TrendPoint> runs;
  for (int i = 0; i < kTrendRuns; ++i)
    runs.push_back({"abc" + std::to_string(1000 + i), 0.002 + 0.0001 * std::sin(i)});
  for (auto _ : state) benchmark::DoNotOptimize(reports::trendChart("relmse", "relmse", runs));
}
BENCHMARK(BM_TrendChart)->Unit(benchmark::kMicrosecond);

void BM_FlipColorBar(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(reports::flipColorBar());
}
BENCHMARK(BM_FlipColorBar)->Unit(benchmark::kMicrosecond);

}  // namespace
