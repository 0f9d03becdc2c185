// `environment_map` (book §4.2.1-4.2.2): a frame at 512² of the `outdoor` scene (a ground, a
// diffuse, a glossy, a mirror and a glass sphere and a torus under the Preetham sky's map), whose
// cost is the shared surface lighting (no light samples: the sky is the only light) plus one
// full-screen pass
// (`frame/environment_ms`); and the convolution the technique runs when it is prepared, against
// the convolved maps' rows (`irradiance_resolution`) and the resampled environment's rows
// (`source_resolution`): its terms grow as the product of the two maps' texels.
#include "realtime/gl/context.h"
#include "realtime/gl/finished_time.h"
#include "realtime/techniques/environment_map/environment_convolution.h"
#include "scene/builtin_scenes.h"
#include "support/technique_frames.h"

namespace gib::rt {
namespace {

void BM_EnvironmentMapFrame(benchmark::State& state) {
  benchmarkTechniqueFrames(state, "environment_map", {}, "outdoor", 512);
}

BENCHMARK(BM_EnvironmentMapFrame)->UseManualTime()->Unit(benchmark::kMillisecond);

// The convolution alone (downsampling on the CPU, upload, one dispatch per layer: the irradiance
// and one glossy exponent), as prepare() runs it.
void BM_EnvironmentMapConvolution(benchmark::State& state) {
  static std::unique_ptr<gl::Context> context = gl::Context::create();
  context->makeCurrent();
  const scene::EnvironmentMap map = scene::loadScene("outdoor", {}).environment;
  const int rows = int(state.range(0)), source_rows = int(state.range(1));
  for (auto _ : state)
    state.SetIterationTime(1e-3 * gl::finishedMilliseconds([&] {
                             const EnvironmentConvolution convolution(map, source_rows, rows,
                                                                      {40.0f});
                           }));
  const double terms = 2.0 * rows * rows * 2 * 2.0 * source_rows * source_rows;
  state.counters["texels_summed"] = terms;
  state.counters["terms_per_second"] =
      benchmark::Counter(terms, benchmark::Counter::kIsIterationInvariantRate);
  state.SetLabel(context->identity().renderer);
}

BENCHMARK(BM_EnvironmentMapConvolution)
    ->Args({32, 64})  // the defaults
    ->Args({16, 64})
    ->Args({64, 64})
    ->Args({32, 128})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gib::rt
