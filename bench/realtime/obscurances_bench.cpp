// `obscurances` (book Ch. 10; issue: "obscurance-map construction time against directions and
// atlas size, and frame time"): the map's construction on the Cornell box, split into its depth
// peeling and its accumulation, against the number of bundles (at the default 128² atlas) and
// against the atlas size (at 64 bundles), both at the default 256² peeling resolution; and a frame
// at 512², whose cost is the shared surface lighting plus one view of the atlas.
#include "realtime/gl/context.h"
#include "realtime/gl/finished_time.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/techniques/obscurances/obscurances_technique.h"
#include "scene/builtin_scenes.h"
#include "support/technique_frames.h"

namespace gib::rt {
namespace {

void obscuranceMapConstruction(benchmark::State& state, int directions, int atlas) {
  static std::unique_ptr<gl::Context> context = gl::Context::create();
  context->makeCurrent();
  const scene::Scene cornell = scene::loadScene("cornell", {});
  const TechniqueInfo& info = findTechnique("obscurances");
  const ParameterValues parameters = parseParameters(
      info.parameters,
      {"directions=" + std::to_string(directions), "atlas=" + std::to_string(atlas)},
      "technique 'obscurances'");
  ObscuranceMapBuild build;
  for (auto _ : state) {
    GpuScene gpu_scene(cornell, 64, 64);
    ObscurancesTechnique technique(parameters);
    state.SetIterationTime(1e-3 *
                           gl::finishedMilliseconds([&] { technique.prepare(gpu_scene, 64, 64); }));
    build = technique.build();
  }
  state.counters["peel_ms"] = build.peel_ms;
  state.counters["accumulate_ms"] = build.accumulate_ms;
  state.counters["normalize_ms"] = build.normalize_ms;
  state.counters["ms_per_bundle"] = (build.peel_ms + build.accumulate_ms) / directions;
  state.counters["layers_mean"] = build.layers_mean;
  state.SetLabel(context->identity().renderer);
}

void BM_ObscuranceMapByDirections(benchmark::State& state) {
  obscuranceMapConstruction(state, int(state.range(0)), 128);
}

BENCHMARK(BM_ObscuranceMapByDirections)
    ->Arg(16)
    ->Arg(64)
    ->Arg(256)
    ->Iterations(1)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

void BM_ObscuranceMapByAtlas(benchmark::State& state) {
  obscuranceMapConstruction(state, 64, int(state.range(0)));
}

BENCHMARK(BM_ObscuranceMapByAtlas)
    ->Arg(64)
    ->Arg(256)
    ->Arg(1024)
    ->Iterations(1)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

void BM_ObscurancesFrame(benchmark::State& state) {
  benchmarkTechniqueFrames(state, "obscurances", {}, "cornell", 512);
}

BENCHMARK(BM_ObscurancesFrame)->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gib::rt
