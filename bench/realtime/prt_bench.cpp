// `prt` (book §8.3): the three costs of the technique apart. The transfer per vertex (Embree ray
// casting of `rays` cosine-distributed rays and bands² basis values per escaping ray) on the
// outdoor scene's torus and ground; CPCA on a set of the size the benchmark cpca_bench.cpp does
// not cover (5000 vectors of one channel's 36 coefficients); and the per-frame projection at the
// book's order 6: the rotation of 36 RGB coefficients about +y and 3·K·(M + 1) dot products of
// 108 values. And a frame at 512² of the torus on the ground (BM_PrtFrame): the shared surface
// lighting, the projection and the vertices' draw, after a preprocessing kept short (64 rays, 1 m
// edges): the frame's cost does not depend on the rays, only on the vertices.
#include "support/technique_frames.h"

#include "realtime/prt/cpca.h"
#include "realtime/techniques/prt/prt_mesh.h"
#include "realtime/techniques/prt/prt_projection.h"
#include "realtime/techniques/prt/prt_transfer.h"

#include "common/splitmix.h"
#include "reference/embree_scene.h"
#include "scene/builtin_scenes.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace gib::rt {
namespace {

constexpr int kBands = 6;

// Arguments: rays per vertex, bounces. Items: vertices.
void BM_PrtTransfer(benchmark::State& state) {
  const scene::Scene scene = scene::loadScene("outdoor", {"objects=torus"});
  // A coarse ground (2 m edges): the torus's vertices, whose rays hit it, weigh as much as the
  // ground's, whose rays escape.
  const prt::PrtMesh mesh = prt::tessellate(scene, 2.0f, 1'000'000);
  const auto caster = ref::embreeRayCasterFactory()(scene);
  prt::TransferSettings settings;
  settings.bands = kBands;
  settings.rays = int(state.range(0));
  settings.bounces = int(state.range(1));
  settings.threads = 1;
  const std::vector<glm::vec3> lighting(std::size_t(kBands * kBands), glm::vec3(1.0f));
  for (auto _ : state) {
    const prt::Transfer transfer = prt::computeTransfer(mesh, scene, *caster, settings, lighting);
    benchmark::DoNotOptimize(transfer.vectors.data());
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(mesh.vertexCount()));
  state.counters["vertices"] = double(mesh.vertexCount());
}
BENCHMARK(BM_PrtTransfer)
    ->Args({256, 1})
    ->Args({1024, 1})
    ->Args({1024, 6})
    ->Unit(benchmark::kMillisecond);

// Smooth vectors as transfer vectors are: a few random directions' basis values, weighted.
std::vector<float> syntheticVectors(int count, int dimension) {
  std::vector<float> vectors(std::size_t(count) * std::size_t(dimension));
  for (int i = 0; i < count; ++i)
    for (int d = 0; d < dimension; ++d) {
      const std::uint64_t h = splitMix64(std::uint64_t(i) * 977u + std::uint64_t(d % 4));
      vectors[std::size_t(i) * std::size_t(dimension) + std::size_t(d)] =
          float(h >> 40) * 0x1.0p-24f / float(1 + d);
    }
  return vectors;
}

void BM_PrtCpca(benchmark::State& state) {
  const int count = int(state.range(0)), dimension = int(state.range(1));
  const std::vector<float> vectors = syntheticVectors(count, dimension);
  for (auto _ : state) {
    const prt::CpcaResult result =
        prt::compressCpca(vectors, dimension, int(state.range(2)), int(state.range(3)), 1);
    benchmark::DoNotOptimize(result.weights.data());
  }
}
BENCHMARK(BM_PrtCpca)->Args({5000, 36, 16, 8})->Unit(benchmark::kMillisecond);

// Arguments: clusters K, basis vectors M. A frame's CPU work at order 6 (108-value vectors).
void BM_PrtLightProjection(benchmark::State& state) {
  prt::CpcaResult compressed;
  compressed.dimension = 3 * kBands * kBands;
  compressed.clusters = int(state.range(0));
  compressed.pca_vectors = int(state.range(1));
  compressed.means = syntheticVectors(compressed.clusters, compressed.dimension);
  compressed.bases =
      syntheticVectors(compressed.clusters * compressed.pca_vectors, compressed.dimension);
  std::vector<glm::vec3> lighting(std::size_t(kBands * kBands));
  for (std::size_t i = 0; i < lighting.size(); ++i) lighting[i] = glm::vec3(1.0f / float(1 + i));
  std::vector<glm::vec3> rotated;
  std::vector<glm::vec4> out(std::size_t(compressed.clusters * (compressed.pca_vectors + 1)));
  float angle = 0.01f;
  for (auto _ : state) {
    prt::projectLighting(compressed, lighting, kBands, angle, rotated, out);
    benchmark::DoNotOptimize(out.data());
    angle += 0.01f;
  }
}
BENCHMARK(BM_PrtLightProjection)->Args({16, 8})->Args({256, 24})->Unit(benchmark::kMicrosecond);

void BM_PrtFrame(benchmark::State& state) {
  benchmarkTechniqueFrames(state, "prt", {"rays=64", "max_edge=1"}, "outdoor", 512, 0,
                           {ref::embreeRayCasterFactory()}, {"objects=torus"});
}
BENCHMARK(BM_PrtFrame)->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gib::rt
