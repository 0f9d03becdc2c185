// Ward's irradiance cache on the CPU against its GPU splatting (course notes 001), on the Cornell
// box at 128 × 96: a frame that rebuilds the cache (what the notes time: records by hemisphere
// sampling, then interpolation) and a frame that reuses it (their ~1 s frames), with the passes
// and the records' statistics (records, records_per_second, record_sampling_ms...) as counters;
// and the octree lookup alone.
#include "realtime/irradiance_cache/record_octree.h"
#include "reference/embree_scene.h"
#include "support/technique_frames.h"

#include <benchmark/benchmark.h>

#include <glm/geometric.hpp>

#include <random>
#include <string>
#include <vector>

namespace {

void BM_IrradianceCacheFrame(benchmark::State& state, const char* reuse) {
  gib::rt::benchmarkTechniqueFrames(state, "irradiance_cache",
                                    {std::string("reuse_records=") + reuse}, "cornell", 96, 128,
                                    {gib::ref::embreeRayCasterFactory()});
}
BENCHMARK_CAPTURE(BM_IrradianceCacheFrame, rebuild, "false")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_IrradianceCacheFrame, reuse, "true")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_IrradianceCacheSplattingFrame(benchmark::State& state, const char* sampling,
                                      const char* reuse) {
  gib::rt::benchmarkTechniqueFrames(
      state, "irradiance_cache_splatting",
      {std::string("sampling=") + sampling, std::string("reuse_records=") + reuse}, "cornell", 96,
      128);
}
BENCHMARK_CAPTURE(BM_IrradianceCacheSplattingFrame, plane_rebuild, "plane", "false")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_IrradianceCacheSplattingFrame, hemicube_rebuild, "hemicube", "false")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_IrradianceCacheSplattingFrame, reuse, "plane", "true")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Lookups of 4 096 records spread over a unit cube's floor with zones of 1–5% of its side.
void BM_RecordOctreeLookup(benchmark::State& state) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(0.0f, 1.0f), radius(0.05f, 0.25f);
  const float a = 0.2f;
  gib::rt::RecordOctree octree({0, 0, 0}, {1, 1, 1}, a);
  for (int i = 0; i < 4096; ++i) {
    gib::rt::gpu::IrradianceRecord r{};
    r.position_radius = glm::vec4(u(rng), 0.0f, u(rng), radius(rng));
    r.normal = glm::vec4(0, 1, 0, 0);
    r.irradiance = glm::vec4(1.0f);
    octree.insert(r);
  }
  std::vector<glm::vec3> points(1024);
  for (glm::vec3& p : points) p = {u(rng), 0.0f, u(rng)};
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(octree.lookup(points[i++ % points.size()], {0, 1, 0}));
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()));
}
BENCHMARK(BM_RecordOctreeLookup);

}  // namespace
