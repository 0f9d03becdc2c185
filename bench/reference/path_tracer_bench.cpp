// Throughput of the reference path tracer on the Cornell box at 512×512, beside bare Embree
// rtcIntersect1 throughput on a comparable ray set in the same run: their ratio is the cost of
// shading, sampling and bookkeeping (the target: the tracer keeps ≥ 60%).
#include "reference/embree_scene.h"
#include "reference/progressive_renderer.h"
#include "reference/rng.h"
#include "reference/sampling.h"
#include "reference/triangle_table.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"

#include <benchmark/benchmark.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <vector>

namespace {

using namespace gib;

constexpr int kSize = 512;

// Samples and rays per second of the reference renderer at 512×512 on a built-in scene;
// state.range(1) is the sampler (the low-discrepancy default, or independent samples).
void BM_Reference512(benchmark::State& state, const char* scene_name) {
  const scene::Scene scene = scene::loadScene(scene_name);
  ref::RenderSettings settings;
  settings.width = settings.height = kSize;
  settings.spp = std::uint32_t(state.range(0));
  settings.sampler = ref::SamplerKind(state.range(1));
  state.SetLabel(ref::samplerName(settings.sampler));
  std::uint64_t rays = 0;
  for (auto _ : state) {
    ref::RenderResult r = ref::renderReference(scene, settings);
    rays += r.rays;
    benchmark::DoNotOptimize(r.mean.data().data());
  }
  state.counters["rays/s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
  state.counters["samples/s"] =
      benchmark::Counter(double(state.iterations()) * kSize * kSize * double(state.range(0)),
                         benchmark::Counter::kIsRate);
}
void bothSamplers(benchmark::internal::Benchmark* b, int spp) {
  b->Args({spp, int(ref::SamplerKind::kSobol)})
      ->Args({spp, int(ref::SamplerKind::kIndependent)})
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
}
// 64 spp on the Cornell box: the progressive passes then hold up to 32 samples of a pixel, so the
// camera rays go to Embree in the coherent batches a reference render uses (at 4 spp the batches
// hold 1–2 rays and the figure would be a start-up cost's).
BENCHMARK_CAPTURE(BM_Reference512, cornell, "cornell")->Apply([](auto* b) { bothSamplers(b, 64); });
BENCHMARK_CAPTURE(BM_Reference512, chamber, "chamber")->Apply([](auto* b) { bothSamplers(b, 1); });
BENCHMARK_CAPTURE(BM_Reference512, cloud, "cloud")->Apply([](auto* b) { bothSamplers(b, 1); });

struct Ray {
  glm::vec3 origin, direction;
};

// Camera rays at 512×512 plus, per pixel, one cosine-distributed ray from a random point on the
// box's surfaces: the mix of coherent and incoherent rays a path tracer issues.
std::vector<Ray> makeRays(const scene::Scene& scene, float epsilon) {
  std::vector<Ray> rays;
  const scene::CameraFrame camera = scene::makeCameraFrame(scene.camera, kSize, kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      rays.push_back(
          {camera.origin, scene::cameraRayDirection(camera, kSize, kSize, x + 0.5f, y + 0.5f)});
  const ref::TriangleTable triangles(scene);
  for (std::uint32_t i = 0; i < std::uint32_t(kSize * kSize); ++i) {
    ref::SampleStream random(7, i, 0);
    const ref::TriangleRecord& t = triangles[i % triangles.size()];
    glm::vec2 b = ref::sampleUniformTriangle({random.next(), random.next()});
    glm::vec3 n = t.normal;
    glm::vec3 p = t.point(b.y, 1.0f - b.x - b.y);
    // Leave from the side facing the box's interior half the time, either side otherwise.
    if (random.next() < 0.5f) n = -n;
    glm::vec3 d =
        ref::Frame(n).toWorld(ref::sampleCosineHemisphere({random.next(), random.next()}));
    rays.push_back({p + epsilon * n, d});
  }
  return rays;
}

void BM_BareEmbreeIntersectCornell(benchmark::State& state) {
  const scene::Scene cornell = scene::loadScene("cornell");
  const ref::EmbreeScene embree(cornell);
  const std::vector<Ray> rays = makeRays(cornell, embree.rayEpsilon());
  for (auto _ : state) {
    std::atomic<std::uint32_t> hits{0};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 4096), [&](auto range) {
      std::uint32_t local = 0;
      for (std::size_t i = range.begin(); i != range.end(); ++i)
        local += embree.intersect(rays[i].origin, rays[i].direction).valid();
      hits += local;
    });
    benchmark::DoNotOptimize(hits.load());
  }
  state.counters["rays/s"] = benchmark::Counter(double(state.iterations()) * double(rays.size()),
                                                benchmark::Counter::kIsRate);
}
BENCHMARK(BM_BareEmbreeIntersectCornell)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
