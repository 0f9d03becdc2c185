// Throughput of the reference path tracer on the Cornell box at 512×512, beside bare Embree
// rtcIntersect1 throughput on a comparable ray set in the same run: their ratio is the cost of
// shading, sampling and bookkeeping (the target: the tracer keeps ≥ 60%).
#include "reference/embree_scene.h"
#include "reference/primary_agreement.h"
#include "reference/progressive_renderer.h"
#include "reference/rng.h"
#include "reference/sampling.h"
#include "reference/triangle_table.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"
#include "support/reference_measures.h"

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

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

// The box-filtered reference beside the pixel-centre one (docs/rendering.md, "Pixel sampling"):
// a pixel-centre render traces each pixel's camera ray once and shares its hit, so its samples
// cost the lighting alone.
void BM_ReferencePixelSampling512(benchmark::State& state) {
  const scene::Scene scene = scene::loadScene("cornell");
  ref::RenderSettings settings;
  settings.width = settings.height = kSize;
  settings.spp = 64;
  settings.pixel_sampling = ref::PixelSampling(state.range(0));
  state.SetLabel(ref::pixelSamplingName(settings.pixel_sampling));
  for (auto _ : state)
    benchmark::DoNotOptimize(ref::renderReference(scene, settings).mean.data().data());
  state.counters["samples/s"] = benchmark::Counter(
      double(state.iterations()) * kSize * kSize * settings.spp, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ReferencePixelSampling512)
    ->Arg(int(ref::PixelSampling::kArea))
    ->Arg(int(ref::PixelSampling::kCenter))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// What a technique job adds after its frames: Embree's ray through every pixel centre compared
// with the rasteriser's surfaces (here a G-buffer made by the same rays, so every pixel agrees).
void BM_ComparePrimarySurfaces512(benchmark::State& state) {
  const scene::Scene scene = scene::loadScene("chamber");
  const ref::EmbreeScene embree(scene);
  const scene::CameraFrame camera = scene::makeCameraFrame(scene.camera, kSize, kSize);
  image::Image position(kSize, kSize, 4), normal(kSize, kSize, 4);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const glm::vec3 d = scene::cameraRayDirection(camera, kSize, kSize, x + 0.5f, y + 0.5f);
      const ref::Hit hit = embree.intersect(camera.origin, d);
      float* p = position.pixel(x, y);
      float* n = normal.pixel(x, y);
      p[3] = hit.valid() ? hit.t : -1.0f;
      if (!hit.valid()) continue;
      const scene::Mesh& mesh = scene.meshes[hit.mesh];
      const glm::uvec3 t = mesh.triangles[hit.triangle];
      const glm::vec3 g = glm::normalize(glm::cross(mesh.positions[t.y] - mesh.positions[t.x],
                                                    mesh.positions[t.z] - mesh.positions[t.x]));
      n[0] = g.x, n[1] = g.y, n[2] = g.z, n[3] = float(mesh.material);
    }
  for (auto _ : state)
    benchmark::DoNotOptimize(ref::comparePrimarySurfaces(scene, position, normal).disagreements);
  state.SetItemsProcessed(std::int64_t(state.iterations()) * kSize * kSize);
}
BENCHMARK(BM_ComparePrimarySurfaces512)->Unit(benchmark::kMillisecond)->UseRealTime();

// Camera rays at 512×512 plus, per pixel, one cosine-distributed ray from a random point on the
// box's surfaces: the mix of coherent and incoherent rays a path tracer issues.
std::vector<scene::Ray> makeRays(const scene::Scene& scene, float epsilon) {
  std::vector<scene::Ray> rays;
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
  bench::measureBareEmbree(state, embree, makeRays(cornell, embree.rayEpsilon()));
}
BENCHMARK(BM_BareEmbreeIntersectCornell)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
