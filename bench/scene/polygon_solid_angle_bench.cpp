// The exact visible solid angle of a partly occluded area light (scene/polygon_solid_angle.h, the
// bench test of Fournier & Péroche §6.1) over a grid of receiver points: what a closed-form
// ground truth per pixel of a shadow image costs.
#include "scene/occluded_light_bench.h"
#include "scene/polygon_solid_angle.h"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

namespace {

using namespace gib;

void BM_VisibleSolidAngle(benchmark::State& state) {
  const scene::OccludedLightBench bench = scene::occludedLightBench();  // 100 × 100 points
  const std::vector<glm::dvec3> points = scene::occludedLightBenchPoints(bench);
  double sum = 0;
  for (auto _ : state) {
    for (const glm::dvec3& x : points)
      sum += scene::visibleSolidAngle(x, bench.light, bench.occluder);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(points.size()));
  state.counters["points/s"] = benchmark::Counter(
      double(state.iterations()) * double(points.size()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_VisibleSolidAngle)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
