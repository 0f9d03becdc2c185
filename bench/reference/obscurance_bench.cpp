// The reference's obscurance (reference/obscurance_estimator.h, docs/rendering.md "Obscurances"):
// rays per second of a whole obscurance render of the Cornell box (camera ray plus one
// obscurance ray per sample) and of the estimator alone at points on the box's surfaces, scalar
// and spectral: what a reference of W costs beside one of radiance.
#include "reference/obscurance_estimator.h"
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace {

using namespace gib;

constexpr int kSize = 128;
constexpr std::uint32_t kSpp = 16;

// state.range(0): the mode (scene::ObscuranceMode).
scene::ObscuranceDefinition definitionOf(const benchmark::State& state) {
  scene::ObscuranceDefinition definition;
  definition.mode = scene::ObscuranceMode(state.range(0));
  return definition;
}

void BM_ObscuranceReferenceCornell128(benchmark::State& state) {
  const scene::Scene cornell = scene::loadScene("cornell");
  ref::RenderSettings settings;
  settings.width = settings.height = kSize;
  settings.spp = kSpp;
  settings.pixel_sampling = ref::PixelSampling::kCenter;
  settings.obscurance = definitionOf(state);
  state.SetLabel(std::string(scene::obscuranceModeName(settings.obscurance->mode)));
  std::uint64_t rays = 0;
  for (auto _ : state) {
    const ref::RenderResult r = ref::renderReference(cornell, settings);
    rays += r.rays;
    benchmark::DoNotOptimize(r.mean.data().data());
  }
  state.counters["rays/s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
  state.counters["samples/s"] = benchmark::Counter(
      double(state.iterations()) * kSize * kSize * kSpp, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ObscuranceReferenceCornell128)
    ->Arg(int(scene::ObscuranceMode::kScalar))
    ->Arg(int(scene::ObscuranceMode::kSpectral))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The estimator alone, on one thread: 16 rays at each of 4096 points at the centres of the box's
// triangles, taken in turn, with their front normals.
void BM_ObscuranceEstimatorCornell(benchmark::State& state) {
  const scene::Scene cornell = scene::loadScene("cornell");
  const ref::ObscuranceEstimator estimator(cornell, definitionOf(state));
  state.SetLabel(std::string(scene::obscuranceModeName(estimator.definition().mode)));
  std::vector<ref::ObscurancePoint> points;
  const ref::TriangleTable& triangles = estimator.triangles();
  for (std::uint32_t i = 0; points.size() < 4096; ++i) {
    const ref::TriangleRecord& t = triangles[i % triangles.size()];
    points.push_back({t.point(1.0f / 3.0f, 1.0f / 3.0f), t.normal});
  }
  std::uint64_t rays = 0;
  for (auto _ : state) {
    const auto estimates = ref::estimateObscurances(estimator, points, 16, rays, /*threads=*/1);
    rays += points.size() * 16;
    benchmark::DoNotOptimize(estimates.data());
  }
  state.counters["rays/s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ObscuranceEstimatorCornell)
    ->Arg(int(scene::ObscuranceMode::kScalar))
    ->Arg(int(scene::ObscuranceMode::kSpectral))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
