// The loose kd-tree of book §5.5 on the CPU (realtime/ray_casting/loose_kd_tree.h): its build on
// the Cornell box and on the chamber at detail 5 (about 85 000 triangles), and the CPU
// traversal's rays per second over seeded random rays from inside the chamber, for the default
// settings and the leaf sizes and block levels its README compares. The GPU traversal is timed
// by `gibench raycast-bench` with the other structures.
#include "common/splitmix.h"
#include "realtime/ray_casting/loose_kd_tree.h"
#include "scene/builtin_scenes.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace {

using namespace gib;

const rt::IvmTriangleSet& cornell() {
  static const rt::IvmTriangleSet set = rt::buildIvmTriangles(scene::loadScene("cornell"));
  return set;
}
const rt::IvmTriangleSet& chamber5() {
  static const rt::IvmTriangleSet set =
      rt::buildIvmTriangles(scene::loadScene("chamber", {"detail=5"}));
  return set;
}

void setCounters(benchmark::State& state, const rt::LooseKdTree& tree) {
  state.counters["triangles"] = double(tree.triangle_order.size());
  state.counters["cuts"] = double(tree.cut_nodes);
  state.counters["leaves"] = double(tree.leaves);
  state.counters["max_depth"] = double(tree.max_depth);
  state.counters["node_KiB"] = double(tree.bytes()) / 1024.0;
  state.counters["sah_cost"] = tree.sah_cost;
}

void BM_LooseKdTreeBuild(benchmark::State& state, const rt::IvmTriangleSet& (*set)()) {
  const rt::IvmTriangleSet& triangles = set();
  rt::LooseKdTree tree;
  for (auto _ : state) {
    tree = rt::buildLooseKdTree(triangles);
    benchmark::DoNotOptimize(tree.nodes.data());
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(triangles.size()));
  setCounters(state, tree);
}
BENCHMARK_CAPTURE(BM_LooseKdTreeBuild, cornell, &cornell)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LooseKdTreeBuild, chamber_detail5, &chamber5)->Unit(benchmark::kMillisecond);

// Rays from uniform points of the chamber's bounds in uniform directions (its hall is closed,
// so nearly all of them hit).
std::vector<std::pair<glm::vec3, glm::vec3>> chamberRays(int count) {
  const rt::IvmTriangleSet& set = chamber5();
  std::vector<std::pair<glm::vec3, glm::vec3>> rays;
  std::uint64_t state = 11;
  auto uniform = [&state] {
    state = splitMix64(state);
    return double(state >> 11) * 0x1.0p-53;
  };
  for (int i = 0; i < count; ++i) {
    const glm::vec3 f{float(uniform()), float(uniform()), float(uniform())};
    const double z = 2.0 * uniform() - 1.0, phi = 2.0 * std::numbers::pi * uniform();
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    rays.emplace_back(set.bounds_min + f * (set.bounds_max - set.bounds_min),
                      glm::vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)));
  }
  return rays;
}

// Arguments: max_leaf_triangles, block_levels.
void BM_LooseKdTreeCpuCast(benchmark::State& state) {
  const rt::IvmTriangleSet& set = chamber5();
  rt::LooseKdTreeSettings settings;
  settings.max_leaf_triangles = int(state.range(0));
  settings.block_levels = int(state.range(1));
  const rt::LooseKdTree tree = rt::buildLooseKdTree(set, settings);
  const auto rays = chamberRays(4096);
  std::size_t hits = 0;
  for (auto _ : state)
    for (const auto& [o, d] : rays) {
      const rt::gpu::RayCastHit hit =
          rt::castLooseKdTree(tree, set, o, d, 0.0f, rt::gpu::kRayInfinity);
      hits += hit.triangle != rt::gpu::kNoRayTriangle;
    }
  benchmark::DoNotOptimize(hits);
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(rays.size()));
  setCounters(state, tree);
  state.counters["blocks"] = double(tree.blocks);
}
BENCHMARK(BM_LooseKdTreeCpuCast)
    ->ArgNames({"leaf", "levels"})
    ->Args({4, rt::gpu::kLooseKdBlockLevels})
    ->Args({2, rt::gpu::kLooseKdBlockLevels})
    ->Args({8, rt::gpu::kLooseKdBlockLevels})
    ->Args({16, rt::gpu::kLooseKdBlockLevels})
    ->Args({4, 3})
    ->Args({4, 5})
    ->Args({4, 6})
    ->Args({4, 8})
    ->Unit(benchmark::kMillisecond);

}  // namespace
