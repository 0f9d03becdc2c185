// What the reference's low-discrepancy sampler buys, side by side with independent samples in one
// run (docs/rendering.md, "Sampling"): the cost of one 2D point, and per built-in scene the
// render's efficiency 1/(MSE · seconds) at equal spp against a long render, and the time an
// image needs to reach relMSE 1e-3 (fitted over its checkpoints, extrapolated).
#include "reference/path_sampler.h"
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"
#include "support/reference_measures.h"

#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <vector>

namespace {

using namespace gib;

void BM_PathSamplerPoint2D(benchmark::State& state) {
  const auto kind = ref::SamplerKind(state.range(0));
  std::uint32_t sample = 0;
  float sum = 0;
  for (auto _ : state) {
    ref::PathSampler sampler(1, 77, sample++, 16, kind);
    for (int vertex = 0; vertex < 8; ++vertex) {
      sampler.startVertex(vertex);
      const glm::vec2 u = sampler.get2D(ref::VertexDimension::kDirection);
      sum += u.x + u.y;
    }
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations() * 8);
  state.SetLabel(kind == ref::SamplerKind::kSobol ? "sobol" : "independent");
}
BENCHMARK(BM_PathSamplerPoint2D)
    ->Arg(int(ref::SamplerKind::kSobol))
    ->Arg(int(ref::SamplerKind::kIndependent));

// The image sizes of the efficiency runs: small, so that the long render fits a benchmark.
constexpr int kWidth = 128, kHeight = 96;
constexpr std::uint32_t kSpp = 256;
constexpr std::uint32_t kTruthSpp = 8192;

// The long render of each scene, made once per process (with the sampler under test's best
// setting: one replica, another seed).
const image::Image& truthOf(const std::string& scene_name) {
  static std::map<std::string, image::Image> truths;
  auto it = truths.find(scene_name);
  if (it == truths.end()) {
    ref::RenderSettings settings;
    settings.width = kWidth;
    settings.height = kHeight;
    settings.spp = kTruthSpp;
    settings.replicas = 1;
    settings.seed = 1000;
    it = truths
             .emplace(scene_name, ref::renderReference(scene::loadScene(scene_name), settings).mean)
             .first;
  }
  return it->second;
}

// state.range(0): the sampler; state.range(1): replicas (0: the default).
void BM_ReferenceEfficiency(benchmark::State& state, const char* scene_name) {
  const scene::Scene scene = scene::loadScene(scene_name);
  const image::Image& truth = truthOf(scene_name);
  ref::RenderSettings settings;
  settings.width = kWidth;
  settings.height = kHeight;
  settings.spp = kSpp;
  settings.sampler = ref::SamplerKind(state.range(0));
  settings.replicas = std::uint32_t(state.range(1));
  bench::measureEfficiency(state, scene, settings, truth);
  state.SetLabel(
      std::string(settings.sampler == ref::SamplerKind::kSobol ? "sobol" : "independent") +
      ", replicas " + std::to_string(ref::replicasOf(settings)));
}

void efficiencyArguments(benchmark::internal::Benchmark* b) {
  // The default (0: 4 replicas at 256 spp), more replicas (the default until 2026-11-26 was 8),
  // and one.
  b->Args({int(ref::SamplerKind::kIndependent), 0})
      ->Args({int(ref::SamplerKind::kSobol), 0})
      ->Args({int(ref::SamplerKind::kSobol), 16})
      ->Args({int(ref::SamplerKind::kSobol), 8})
      ->Args({int(ref::SamplerKind::kSobol), 1})
      ->Iterations(2)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
}
BENCHMARK_CAPTURE(BM_ReferenceEfficiency, cornell, "cornell")->Apply(efficiencyArguments);
BENCHMARK_CAPTURE(BM_ReferenceEfficiency, chamber, "chamber")->Apply(efficiencyArguments);
BENCHMARK_CAPTURE(BM_ReferenceEfficiency, cloud, "cloud")->Apply(efficiencyArguments);

}  // namespace
