// Hardware sampling of an area light (Fournier & Péroche §4): one point's sample per iteration,
// on the bench geometry of §6.1, with the three phases of the paper's Fig. 9 as counters (their
// means over the iterations; `gibench solid-angle-bench` reports medians and quartiles).
#include "realtime/gl/context.h"
#include "realtime/techniques/jittered_light_sampling/solid_angle_bench.h"
#include "support/technique_frames.h"

#include <benchmark/benchmark.h>

#include <memory>

namespace {

using namespace gib;

void BM_LightCoverageSample(benchmark::State& state, const char* scheme) {
  static std::unique_ptr<rt::gl::Context> context = rt::gl::Context::create();
  rt::CoverageSettings settings;
  rt::parseCoverageScheme(scheme, settings);
  settings.size = int(state.range(0));
  const scene::OccludedLightBench b = scene::occludedLightBench();
  rt::LightCoverageSampler sampler(rt::quadTriangles(b.light), rt::quadTriangles(b.occluder),
                                   settings);
  const std::vector<glm::dvec3> points = scene::occludedLightBenchPoints(b);
  rt::CoveragePhaseTimes sum;
  std::uint32_t i = 0;
  for (auto _ : state) {
    rt::CoveragePhaseTimes t;
    benchmark::DoNotOptimize(sampler.visibleSolidAngle(points[i % points.size()], i, &t));
    sum.render_ms += t.render_ms;
    sum.read_back_ms += t.read_back_ms;
    sum.weight_ms += t.weight_ms;
    ++i;
  }
  const double n = double(state.iterations());
  state.counters["render_ms"] = sum.render_ms / n;
  state.counters["read_back_ms"] = sum.read_back_ms / n;
  state.counters["weight_ms"] = sum.weight_ms / n;
  state.SetLabel(context->identity().renderer);
}
void sizes(benchmark::internal::Benchmark* b) {
  b->Arg(32)->Arg(48)->Arg(64)->Unit(benchmark::kMicrosecond);
}
BENCHMARK_CAPTURE(BM_LightCoverageSample, occlusion_query, "occlusion_query")->Apply(sizes);
BENCHMARK_CAPTURE(BM_LightCoverageSample, regular, "regular")->Apply(sizes);
BENCHMARK_CAPTURE(BM_LightCoverageSample, jittered1, "jittered1")->Apply(sizes);
BENCHMARK_CAPTURE(BM_LightCoverageSample, jittered4, "jittered4")->Apply(sizes);
BENCHMARK_CAPTURE(BM_LightCoverageSample, jittered8, "jittered8")->Apply(sizes);

// The technique's frame on the Cornell box at 64² (4096 points, two batches), per scheme: the
// counters are its passes' medians (coverage, weighing).
void BM_JitteredLightSamplingFrame(benchmark::State& state, const char* scheme, const char* spp) {
  rt::benchmarkTechniqueFrames(
      state, "jittered_light_sampling",
      {std::string("scheme=") + scheme, std::string("samples_per_pixel=") + spp,
       "sampling_size=" + std::to_string(state.range(0))},
      "cornell", 64);
}
void frameSizes(benchmark::internal::Benchmark* b) {
  b->Arg(32)->Arg(64)->Unit(benchmark::kMillisecond)->UseRealTime();
}
BENCHMARK_CAPTURE(BM_JitteredLightSamplingFrame, regular, "regular", "1")->Apply(frameSizes);
BENCHMARK_CAPTURE(BM_JitteredLightSamplingFrame, jittered1, "jittered", "1")->Apply(frameSizes);
BENCHMARK_CAPTURE(BM_JitteredLightSamplingFrame, jittered4, "jittered", "4")->Apply(frameSizes);

}  // namespace
