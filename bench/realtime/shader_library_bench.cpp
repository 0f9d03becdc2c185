// Expanding a stage's #includes (the shared `*_shared.h` headers among them, with their
// `#ifdef __cplusplus` blocks dropped) happens for every program a technique builds in prepare();
// it must stay a negligible part of a technique's preparation.
#include "realtime/gl/shader_library.h"

#include <benchmark/benchmark.h>

namespace {

using namespace gib::rt;

void BM_ExpandIncludes(benchmark::State& state, const char* path) {
  std::size_t bytes = 0;
  for (auto _ : state) {
    const gl::ExpandedSource source = gl::expandIncludes(path, "#define POINT_LIGHT 1\n");
    bytes = source.text.size();
    benchmark::DoNotOptimize(source.text.data());
  }
  state.SetBytesProcessed(state.iterations() * std::int64_t(bytes));
}
BENCHMARK_CAPTURE(BM_ExpandIncludes, irradiance_volume_indirect,
                  "realtime/techniques/irradiance_volume/indirect.frag.glsl")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ExpandIncludes, radiosity_update,
                  "realtime/techniques/stochastic_radiosity/update.frag.glsl")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ExpandIncludes, shade_light, "realtime/lighting/shade_light.frag.glsl")
    ->Unit(benchmark::kMicrosecond);

}  // namespace
