// `environment_shadows` (book §4.2.3): the cells' construction on the CPU (radiance-proportional
// centres, 8 weighted Lloyd steps, the powers) on the Preetham sky's 128 × 256 map, for 64, 256
// and 1000 cells (Fig. 4.15 uses 1000); and a frame of the outdoor scene (objects=diffuse: the
// technique renders no mirrors or glass) at 256² with 16 and 64 cells, whose
// `frame/lights/shadow_map` pass over the cells is the shadow pass per cell (per cell: that pass
// time over `lit_cells`; the frame time over the cells bounds it).
#include "realtime/environment_cells/environment_cells.h"
#include "scene/preetham_sky.h"
#include "support/technique_frames.h"

#include <benchmark/benchmark.h>

#include <string>

namespace gib::rt {
namespace {

void BM_EnvironmentCells(benchmark::State& state) {
  scene::SkyParameters sky;
  sky.height = 128;
  const scene::EnvironmentMap map = scene::makePreethamSky(sky);
  const int cells = int(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(buildEnvironmentCells(map, cells, 8));
  state.counters["texels"] = double(map.width * map.height);
}

BENCHMARK(BM_EnvironmentCells)->Arg(64)->Arg(256)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_EnvironmentShadowsFrame(benchmark::State& state) {
  const int cells = int(state.range(0));
  benchmarkTechniqueFrames(state, "environment_shadows", {"cells=" + std::to_string(cells)},
                           "outdoor", 256, 0, {}, {"objects=diffuse"});
  state.counters["cells"] = cells;
}

BENCHMARK(BM_EnvironmentShadowsFrame)
    ->Arg(16)
    ->Arg(64)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gib::rt
