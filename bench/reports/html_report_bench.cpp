// The HTML report of a nightly-sized run (50 technique jobs with nested pass timings and
// convergence, coloured against a previous run, trends over 20 runs), and each SVG chart alone;
// and how long the index of a 100-job run (128² pictures, thumbnails, viewer data) takes to load
// in headless Chromium, measured by the page itself (navigation to load event).
#include "reports/figure_composite.h"
#include "reports/html_report.h"
#include "reports/junit_report.h"
#include "reports/markdown_summary.h"
#include "reports/run_comparison.h"
#include "reports/svg_charts.h"
#include "support/headless_browser.h"
#include "support/synthetic_report_run.h"
#include "support/temporary_directory.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

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

// 100 jobs at the nightly suite's 128², regressed against a previous run so the regressed-first
// view is on the page too.
struct LoadFixture {
  static constexpr int kLoadJobs = 100;
  const bench::TemporaryDirectory temporary{"gib-report-load-bench"};
  const fs::path& dir = temporary.path();
  fs::path index;
  LoadFixture() {
    results::RunResults results = test::syntheticReportResults("20261122-100405-nightly-1a2b3c4d");
    results.jobs.resize(1);  // the reference
    for (int i = 0; i < kLoadJobs - 1; ++i) {
      results::JobResult job =
          test::syntheticTechniqueJob("light_samples=" + std::to_string(i + 1), 0.002 / (i + 1));
      job.width = job.height = 128;
      results.jobs.push_back(job);
    }
    results.jobs[0].width = results.jobs[0].height = 128;
    test::writeSyntheticOutputs(dir, results);
    results::RunResults previous = results;
    previous.run.id = "20261121-100405-nightly-00000000";
    previous.run.started = "2026-11-21T10:04:05Z";
    for (int i = 1; i < kLoadJobs; i += 10) previous.jobs[i].metrics[0].second *= 0.5;
    reports::ReportContext context;
    context.previous = previous;
    index = writeHtmlReport(dir, results, context);
  }
};

// The bytes a browser reads to show a page: the page and every file its src attributes name.
std::uintmax_t pageWeight(const fs::path& page) {
  std::ifstream in(page);
  std::stringstream text;
  text << in.rdbuf();
  const std::string html = text.str();
  std::uintmax_t bytes = fs::file_size(page);
  const std::regex source(R"re(src="([^"]+)")re");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), source);
       it != std::sregex_iterator(); ++it) {
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(page.parent_path() / (*it)[1].str(), ec);
    if (!ec) bytes += size;
  }
  return bytes;
}

// Wall time per iteration is the browser's whole start; the counter load_ms is what a reader
// waits for: the page's own navigation-to-load time.
void BM_IndexOf100JobsLoadsInChromium(benchmark::State& state) {
  const std::optional<fs::path> chromium = test::findChromium();
  if (!chromium) {
    state.SkipWithError("no chromium (scripts/install-deps.sh installs it)");
    return;
  }
  static LoadFixture fixture;
  double load_ms = 0;
  for (auto _ : state) {
    const test::LoadedPage page =
        test::loadPage(*chromium, fixture.index, fixture.dir, test::PageClock::kReal);
    const std::string value = test::rootAttribute(page.dom, "data-load-ms");
    if (page.exit_code != 0 || value.empty() || test::reportCheck(page.dom) != "ok") {
      state.SkipWithError(("the index did not load: " + test::reportCheck(page.dom)).c_str());
      return;
    }
    load_ms += std::stod(value);
  }
  state.counters["load_ms"] = load_ms / double(state.iterations());
  state.counters["page_bytes"] = double(pageWeight(fixture.index));
}
BENCHMARK(BM_IndexOf100JobsLoadsInChromium)->Unit(benchmark::kMillisecond)->Iterations(3);

// The CI outputs of the same 50-job run against its previous run: the comparison (shared by
// the report), then the JUnit XML and the Markdown summary.
void BM_JunitAndSummary50Jobs(benchmark::State& state) {
  static ReportFixture fixture;
  for (auto _ : state) {
    const reports::RunComparison comparison(fixture.results, fixture.context.previous,
                                            fixture.context.history);
    benchmark::DoNotOptimize(reports::junitReport(fixture.results, comparison, fixture.dir));
    benchmark::DoNotOptimize(reports::markdownSummary(fixture.results, comparison, fixture.dir));
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * kJobs);
}
BENCHMARK(BM_JunitAndSummary50Jobs)->Unit(benchmark::kMillisecond);

// A figure's PNG: the synthetic run's figure, its panels read, composited and written.
void BM_FigureComposite(benchmark::State& state) {
  const bench::TemporaryDirectory temporary{"gib-figure-bench"};
  const results::RunResults results = test::syntheticReportResults();
  test::writeSyntheticOutputs(temporary.path(), results);
  const fs::path target = temporary.path() / "figure.png";
  for (auto _ : state)
    benchmark::DoNotOptimize(
        reports::writeFigurePng(temporary.path(), results, results.figures.front(), target));
}
BENCHMARK(BM_FigureComposite)->Unit(benchmark::kMicrosecond);

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
