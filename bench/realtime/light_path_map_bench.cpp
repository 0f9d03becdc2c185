// `light_path_map` on the chamber (issue: "preprocessing per stage and frame time per pass"): the
// preprocessing's three stages (the ray caster's BVH, light tracing on the CPU, the panes on the
// GPU) for 256 and 1024 entry points, and a frame at the book's 1024×768 with its 256 clusters and
// 32 panes. The frame's cost does not depend on the entry point count (one fragment each in the
// weights pass), so its benchmark prepares 1024 of them rather than the book's 4096, which on
// llvmpipe take a minute. Embree is lent as the harness lends it (TechniqueServices).
#include "realtime/gl/context.h"
#include "realtime/gl/finished_time.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/techniques/light_path_map/light_path_map_technique.h"
#include "reference/embree_scene.h"
#include "scene/builtin_scenes.h"
#include "support/technique_frames.h"

namespace gib::rt {
namespace {

void BM_LightPathMapPreprocessing(benchmark::State& state) {
  static std::unique_ptr<gl::Context> context = gl::Context::create();
  context->makeCurrent();
  const scene::Scene chamber = scene::loadScene("chamber", {});
  LightPathMapSettings settings;
  settings.entry_points = int(state.range(0));
  LightPathMapPreprocessing stages;
  for (auto _ : state) {
    GpuScene gpu_scene(chamber, 64, 64);
    LightPathMapTechnique technique(settings);
    technique.provide({ref::embreeRayCasterFactory()});
    state.SetIterationTime(1e-3 *
                           gl::finishedMilliseconds([&] { technique.prepare(gpu_scene, 64, 64); }));
    stages = technique.preprocessing();
  }
  state.counters["ray_caster_ms"] = stages.ray_caster_ms;
  state.counters["light_tracing_ms"] = stages.light_tracing_ms;
  state.counters["lpm_ms"] = stages.lpm_ms;
  state.counters["virtual_lights"] = double(stages.virtual_lights);
  state.counters["us_per_virtual_light"] =
      1e3 * stages.lpm_ms / double(std::max<std::size_t>(stages.virtual_lights, 1));
  state.SetLabel(context->identity().renderer);
}

BENCHMARK(BM_LightPathMapPreprocessing)
    ->Arg(256)
    ->Arg(1024)
    ->Iterations(1)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

void BM_LightPathMapFrame(benchmark::State& state) {
  benchmarkTechniqueFrames(state, "light_path_map", {"entry_points=1024"}, "chamber", 768, 1024,
                           {ref::embreeRayCasterFactory()});
}

BENCHMARK(BM_LightPathMapFrame)->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gib::rt
