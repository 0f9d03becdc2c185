// The BVH of the ray-casting table (realtime/ray_casting/bvh.h) on the CPU: its binned-SAH build
// on the Cornell box and on the chamber at detail 1 and 5 (about 3 400 and 85 000 triangles), and
// its CPU traversal (the tests' reference for the GPU) in rays/s on uniform random rays from
// points of the scene's bounds. The GPU's rays/s are `gibench raycast-bench`'s.
#include "common/splitmix.h"
#include "realtime/ray_casting/bvh.h"
#include "scene/builtin_scenes.h"

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

namespace gib::rt {
namespace {

// The triangle set of a scene, made once per process (the chamber at detail 5 takes a while).
const IvmTriangleSet& triangleSet(const std::string& scene, int detail) {
  static std::map<std::pair<std::string, int>, IvmTriangleSet> sets;
  const auto key = std::make_pair(scene, detail);
  auto found = sets.find(key);
  if (found == sets.end()) {
    const std::vector<std::string> parameters =
        scene == "chamber" ? std::vector<std::string>{"detail=" + std::to_string(detail)}
                           : std::vector<std::string>{};
    found = sets.emplace(key, buildIvmTriangles(scene::loadScene(scene, parameters))).first;
  }
  return found->second;
}

void buildOn(benchmark::State& state, const IvmTriangleSet& set) {
  Bvh bvh;
  for (auto _ : state) {
    bvh = buildBvh(set);
    benchmark::DoNotOptimize(bvh.nodes.data());
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(set.size()));
  state.counters["triangles"] = double(set.size());
  state.counters["inner_nodes"] = double(bvh.inner_nodes);
  state.counters["max_depth"] = double(bvh.max_depth);
  state.counters["sah_cost"] = bvh.sah_cost;
  state.counters["node_bytes"] = double(bvh.bytes());
}

void BM_BvhBuildCornell(benchmark::State& state) {
  buildOn(state, triangleSet("cornell", 1));
}
BENCHMARK(BM_BvhBuildCornell)->Unit(benchmark::kMicrosecond);

void BM_BvhBuildChamber(benchmark::State& state) {
  buildOn(state, triangleSet("chamber", int(state.range(0))));
}
BENCHMARK(BM_BvhBuildChamber)->Arg(1)->Arg(5)->Unit(benchmark::kMillisecond);

// Rays/s of castBvh, one thread, over 4096 rays cast again each iteration.
void castOn(benchmark::State& state, const IvmTriangleSet& set) {
  const Bvh bvh = buildBvh(set);
  struct Ray {
    glm::vec3 o, d;
  };
  std::vector<Ray> rays;
  std::uint64_t s = 1234;
  const auto next = [&] {
    s = splitMix64(s);
    return double(s >> 11) * 0x1.0p-53;
  };
  for (int i = 0; i < 4096; ++i) {
    // Braces: their arguments are evaluated in order, so the rays are the same on every compiler.
    const glm::vec3 f{float(next()), float(next()), float(next())};
    const double z = 2.0 * next() - 1.0, phi = 2.0 * std::numbers::pi * next();
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    rays.push_back({set.bounds_min + f * (set.bounds_max - set.bounds_min),
                    glm::vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z))});
  }
  std::size_t hits = 0;
  for (auto _ : state)
    for (const Ray& ray : rays)
      hits +=
          castBvh(bvh, set, ray.o, ray.d, 0.0f, gpu::kRayInfinity).triangle != gpu::kNoRayTriangle;
  // items_per_second is rays/s.
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(rays.size()));
  state.counters["hit_fraction"] = double(hits) / double(state.iterations() * rays.size());
}

void BM_BvhCastCpuCornell(benchmark::State& state) {
  castOn(state, triangleSet("cornell", 1));
}
BENCHMARK(BM_BvhCastCpuCornell)->Unit(benchmark::kMillisecond);

void BM_BvhCastCpuChamber(benchmark::State& state) {
  castOn(state, triangleSet("chamber", int(state.range(0))));
}
BENCHMARK(BM_BvhCastCpuChamber)->Arg(1)->Arg(5)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gib::rt
