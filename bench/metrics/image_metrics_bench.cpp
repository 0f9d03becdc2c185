// Every non-FLIP metric on a 1024×768 pair (the budget: under 50 ms each on 2 cores).
#include "metrics/image_metrics.h"
#include "metrics/metric_registry.h"
#include "metrics/ssim.h"
#include "metrics/z_test.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

using namespace gib;

constexpr int kWidth = 1024;
constexpr int kHeight = 768;

struct Pair {
  image::Image reference{kWidth, kHeight};
  image::Image test{kWidth, kHeight};
  Pair() {
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x)
        for (int c = 0; c < 3; ++c) {
          float v = 0.5f + 0.4f * std::sin(0.01f * float(x * (c + 1)) + 0.02f * float(y));
          reference.pixel(x, y)[c] = v;
          test.pixel(x, y)[c] = v + 0.05f * std::sin(float(x * 31 + y * 17 + c));
        }
  }
};

const Pair& pair() {
  static const Pair p;
  return p;
}

template <metrics::MetricValue (*Metric)(const image::Image&, const image::Image&)>
void BM_Metric(benchmark::State& state) {
  const Pair& p = pair();
  for (auto _ : state) benchmark::DoNotOptimize(Metric(p.reference, p.test).value);
  state.SetItemsProcessed(std::int64_t(state.iterations()) * kWidth * kHeight);
}

metrics::MetricValue relMse(const image::Image& r, const image::Image& t) {
  return metrics::computeRelMse(r, t);
}
metrics::MetricValue relMseRejectingOutliers(const image::Image& r, const image::Image& t) {
  return metrics::computeRelMse(r, t, metrics::kRelativeEpsilon, true);
}
metrics::MetricValue mape(const image::Image& r, const image::Image& t) {
  return metrics::computeMape(r, t);
}
metrics::MetricValue smape(const image::Image& r, const image::Image& t) {
  return metrics::computeSmape(r, t);
}

BENCHMARK(BM_Metric<metrics::computeMse>)
    ->Name("BM_Mse_1024x768")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Metric<metrics::computeRmse>)
    ->Name("BM_Rmse_1024x768")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Metric<metrics::computeMae>)
    ->Name("BM_Mae_1024x768")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Metric<relMse>)
    ->Name("BM_RelMse_1024x768")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Metric<relMseRejectingOutliers>)
    ->Name("BM_RelMseRejectOutliers_1024x768")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Metric<mape>)->Name("BM_Mape_1024x768")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Metric<smape>)
    ->Name("BM_Smape_1024x768")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Metric<metrics::computePsnr>)
    ->Name("BM_Psnr_1024x768")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Metric<metrics::computeSsim>)
    ->Name("BM_Ssim_1024x768")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// relMSE as every comparison reports it (metrics/metric_registry.h): with its concentration,
// the share of the worst 0.1 % and 1 % of pixels (one sort of the per-pixel values). Beside
// BM_RelMse_1024x768 in one run, the ratio is the concentration's cost.
void BM_RelMseWithConcentration_1024x768(benchmark::State& state) {
  const Pair& p = pair();
  for (auto _ : state)
    benchmark::DoNotOptimize(metrics::evaluateMetrics(p.reference, p.test, {"relmse"}).values);
  state.SetItemsProcessed(std::int64_t(state.iterations()) * kWidth * kHeight);
}
BENCHMARK(BM_RelMseWithConcentration_1024x768)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ZTest_1024x768(benchmark::State& state) {
  const Pair& p = pair();
  const image::Image variance(kWidth, kHeight, 3, 1e-3f);
  for (auto _ : state)
    benchmark::DoNotOptimize(metrics::zTest(p.reference, variance, p.test, variance).failing);
  state.SetItemsProcessed(std::int64_t(state.iterations()) * kWidth * kHeight);
}
BENCHMARK(BM_ZTest_1024x768)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
