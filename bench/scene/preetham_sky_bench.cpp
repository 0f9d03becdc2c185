// The Preetham sky map (scene/preetham_sky.h) at three sizes: what `gibench sky` and a scene that
// builds its sky on load pay. Texels per second, the sky's rows spread over the hardware threads.
#include "scene/preetham_sky.h"

#include <benchmark/benchmark.h>

#include <cstdint>

namespace {

using namespace gib;

void BM_PreethamSky(benchmark::State& state) {
  scene::SkyParameters parameters;
  parameters.height = int(state.range(0));
  for (auto _ : state) {
    scene::EnvironmentMap map = scene::makePreethamSky(parameters);
    benchmark::DoNotOptimize(map.texels->data());
  }
  const std::int64_t texels = 2 * state.range(0) * state.range(0);
  state.SetItemsProcessed(state.iterations() * texels);
  state.counters["texels/s"] =
      benchmark::Counter(double(state.iterations()) * double(texels), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_PreethamSky)
    ->Arg(64)
    ->Arg(256)
    ->Arg(1024)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
