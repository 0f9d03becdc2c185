// The environment map's importance distribution (scene/environment_distribution.h): its set-up,
// paid once per render and per technique that draws light samples from the map, and a draw and a
// density lookup, paid at every vertex of every reference path (next-event estimation and the MIS
// weight of a path that leaves the scene). On the Preetham sky of each size.
#include "scene/environment_distribution.h"
#include "scene/preetham_sky.h"

#include <benchmark/benchmark.h>

#include <cstdint>

namespace {

using namespace gib;

scene::EnvironmentMap sky(std::int64_t height) {
  scene::SkyParameters parameters;
  parameters.height = int(height);
  return scene::makePreethamSky(parameters);
}

void BM_EnvironmentDistributionSetUp(benchmark::State& state) {
  const scene::EnvironmentMap map = sky(state.range(0));
  for (auto _ : state) {
    scene::EnvironmentDistribution distribution(map);
    benchmark::DoNotOptimize(&distribution);
  }
  state.counters["texels/s"] = benchmark::Counter(
      double(state.iterations()) * double(map.width) * map.height, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_EnvironmentDistributionSetUp)
    ->Arg(128)
    ->Arg(512)
    ->Arg(2048)
    ->Unit(benchmark::kMillisecond);

// A draw and the density of the drawn direction, as the path tracer pays them at a vertex.
void BM_EnvironmentDistributionSample(benchmark::State& state) {
  const scene::EnvironmentMap map = sky(state.range(0));
  const scene::EnvironmentDistribution distribution(map);
  std::uint32_t i = 0;
  for (auto _ : state) {
    // Two Weyl sequences (golden-ratio and √2 steps): uniform, cheap, every cdf range is hit.
    const glm::vec2 u{float((i * 0x9E3779B9u) >> 8) * 0x1p-24f,
                      float((i * 0x6A09E667u) >> 8) * 0x1p-24f};
    ++i;
    const scene::EnvironmentSample s = distribution.sample(u);
    benchmark::DoNotOptimize(distribution.pdf(s.direction) + s.pdf);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EnvironmentDistributionSample)->Arg(128)->Arg(512)->Arg(2048);

}  // namespace
