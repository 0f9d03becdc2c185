// The loose kd-tree of book §5.5 (realtime/ray_casting/loose_kd_tree.h): its packed words are a
// partition of the triangles into leaves whose decoded, rounded cells hold them; it is built the
// same way every time, within the stack's depth and the leaves' 255 triangles; its CPU traversal
// finds the brute force's closest hit, rays along the axes and in the cut planes included; the
// GPU's traversal finds the CPU traversal's.
#include "realtime/ray_casting/loose_kd_tree.h"

#include "common/splitmix.h"
#include "realtime/ray_casting/ray_cast_pass.h"
#include "realtime/ray_casting/ray_structures.h"
#include "scene/builtin_scenes.h"
#include "support/cast_rays.h"
#include "support/gl_test_context.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace gib::rt {
namespace {

// Two casts agree when they name the same triangle, or when both hit and their t differ by at
// most this fraction of the scene's diagonal: two triangles that meet where the ray crosses (a
// shared edge, a corner of the box) tie within the IVM test's rounding, and which one a traversal
// meets first decides the winner. 10⁻⁵ is the tie rule of hit_comparison.h.
constexpr float kTieFraction = 1e-5f;

struct Scenes {
  IvmTriangleSet cornell = buildIvmTriangles(scene::loadScene("cornell"));
  // Detail 1 (about 3 400 triangles) keeps the brute force and llvmpipe quick.
  IvmTriangleSet chamber = buildIvmTriangles(scene::loadScene("chamber", {"detail=1"}));
  LooseKdTree cornell_tree = buildLooseKdTree(cornell);
  LooseKdTree chamber_tree = buildLooseKdTree(chamber);
};

const Scenes& scenes() {
  static const Scenes s;
  return s;
}

// A cut node's decoded planes and axis, for the walks below.
struct DecodedCut {
  int axis;
  glm::vec2 planes;
};

// Rays whose direction has components exactly 0 (along the six axes, and diagonals in the
// coordinate planes), from random origins and from origins lying exactly in the root's cut
// planes (decoded), so that a ray parallel to a cut runs in its plane: (plane − o)·(1/d) is
// 0·∞ there.
std::vector<CastRay> axisRays(const IvmTriangleSet& set, const LooseKdTree& tree, int count,
                              std::uint64_t seed) {
  const float s = std::sqrt(0.5f);
  const std::vector<glm::vec3> directions = {
      {1, 0, 0}, {-1, 0, 0}, {0, 1, 0},  {0, -1, 0},  {0, 0, 1},     {0, 0, -1},
      {s, s, 0}, {-s, 0, s}, {0, s, -s}, {0, -s, -s}, {-0.0f, 0, 1}, {0, -0.0f, -1}};
  // The planes of the first cuts of block 0 (its internal levels are never pointers).
  std::vector<DecodedCut> cuts;
  for (std::size_t slot = 0; slot < std::size_t(gpu::kLooseKdFirstLastLevelNode); ++slot)
    if (tree.flags[slot] != gpu::kLooseKdLeafFlag)
      cuts.push_back({int(tree.flags[slot]), gpu::looseKdCutPlanes(tree.nodes[slot])});
  std::vector<CastRay> rays;
  std::uint64_t state = seed;
  for (int i = 0; i < count; ++i) {
    CastRay ray;
    // Braces: evaluated in order, so the rays are the same on every compiler.
    const glm::vec3 f{float(test::unitUniform(state)), float(test::unitUniform(state)),
                      float(test::unitUniform(state))};
    ray.origin = set.bounds_min + f * (set.bounds_max - set.bounds_min);
    ray.direction = directions[std::size_t(i) % directions.size()];
    if (i % 2 == 1 && !cuts.empty()) {
      // In a cut plane, moving parallel to it (the direction's component along the axis is 0).
      const DecodedCut& cut = cuts[std::size_t(test::unitUniform(state) * double(cuts.size()))];
      const float plane = (i / 2) % 2 == 0 ? cut.planes.x : cut.planes.y;
      if (std::isfinite(plane)) ray.origin[cut.axis] = plane;
      ray.direction[cut.axis] = 0.0f;
      if (glm::dot(ray.direction, ray.direction) == 0.0f) ray.direction[(cut.axis + 1) % 3] = 1.0f;
    }
    rays.push_back(ray);
  }
  return rays;
}

void expectCpuAgreesWithBruteForce(const IvmTriangleSet& set, const LooseKdTree& tree,
                                   const std::vector<CastRay>& rays) {
  const float tie = kTieFraction * glm::length(set.bounds_max - set.bounds_min);
  int disagreements = 0, hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const CastRay& r = rays[i];
    const gpu::RayCastHit expected = castBruteForce(set, r.origin, r.direction, r.t_min, r.t_max);
    const gpu::RayCastHit got = castLooseKdTree(tree, set, r.origin, r.direction, r.t_min, r.t_max);
    if (expected.triangle != gpu::kNoRayTriangle) ++hits;
    if (!test::sameCastHit(expected, got, tie) && ++disagreements <= 5)
      ADD_FAILURE() << "ray " << i << ": brute force " << expected.triangle << " at t "
                    << expected.t << ", loose kd-tree " << got.triangle << " at t " << got.t;
  }
  EXPECT_EQ(disagreements, 0) << "of " << rays.size() << " rays";
  // The rays must mostly hit something, or agreeing would say little.
  EXPECT_GT(hits, int(rays.size()) / 2);
}

// Walks the packed words from the root as the traversal does, intersecting the decoded planes
// of every cut on the way into each leaf's cell; checks each leaf's triangles against it and
// counts each slot's leaves.
struct Walk {
  std::vector<int> slot_leaves;
  std::size_t cuts = 0, pointers = 0, leaves = 0, empty_leaves = 0, outside = 0;
  int max_depth = 0;
};

void walk(const LooseKdTree& tree, const IvmTriangleSet& set, std::uint32_t slot, glm::vec3 lo,
          glm::vec3 hi, int depth, Walk& w) {
  const std::uint32_t levels = std::uint32_t(tree.block_levels);
  const std::uint32_t mask = (1u << levels) - 1u;
  const std::uint32_t first_last = (1u << (levels - 1u)) - 1u;
  ASSERT_LT(slot, tree.nodes.size());
  const std::uint32_t flag = tree.flags[slot];
  ASSERT_LE(flag, gpu::kLooseKdLeafFlag);
  if (flag == gpu::kLooseKdLeafFlag) {
    const std::uint32_t start = gpu::looseKdLeafStart(tree.nodes[slot]);
    const std::uint32_t count = gpu::looseKdLeafCount(tree.nodes[slot]);
    ASSERT_LE(std::size_t(start) + count, tree.triangle_order.size());
    count > 0 ? ++w.leaves : ++w.empty_leaves;
    w.max_depth = std::max(w.max_depth, depth);
    for (std::uint32_t s = start; s < start + count; ++s) {
      ++w.slot_leaves[s];
      const IvmTriangle& t = set.triangles[tree.triangle_order[s]];
      for (const glm::vec3& v : {t.a, t.b, t.c})
        for (int a = 0; a < 3; ++a)
          if (!(v[a] >= lo[a] && v[a] <= hi[a])) ++w.outside;
    }
    return;
  }
  if ((slot & mask) >= first_last) {
    ++w.pointers;
    slot = tree.nodes[slot] << levels;
    ASSERT_LT(slot, tree.nodes.size());
    ASSERT_EQ(tree.flags[slot], flag) << "a pointer's flags name its target's axis";
  }
  ++w.cuts;
  const glm::vec2 planes = gpu::looseKdCutPlanes(tree.nodes[slot]);
  const std::uint32_t in_block = slot & mask;
  const std::uint32_t left = slot - in_block + 2u * in_block + 1u;
  glm::vec3 left_hi = hi, right_lo = lo;
  left_hi[flag] = std::min(hi[flag], planes.x);
  right_lo[flag] = std::max(lo[flag], planes.y);
  walk(tree, set, left, lo, left_hi, depth + 1, w);
  walk(tree, set, left + 1u, right_lo, hi, depth + 1, w);
}

Walk walkTree(const LooseKdTree& tree, const IvmTriangleSet& set) {
  Walk w;
  w.slot_leaves.assign(tree.triangle_order.size(), 0);
  const float inf = std::numeric_limits<float>::infinity();
  walk(tree, set, 0, glm::vec3(-inf), glm::vec3(inf), 0, w);
  return w;
}

void expectPartitionInsideCells(const LooseKdTree& tree, const IvmTriangleSet& set) {
  ASSERT_EQ(tree.triangle_order.size(), set.size());
  std::vector<int> seen(set.size(), 0);
  for (std::uint32_t index : tree.triangle_order) ++seen[index];
  for (std::size_t i = 0; i < set.size(); ++i) ASSERT_EQ(seen[i], 1) << "triangle " << i;
  const Walk w = walkTree(tree, set);
  for (std::size_t s = 0; s < w.slot_leaves.size(); ++s)
    ASSERT_EQ(w.slot_leaves[s], 1) << "slot " << s << " in " << w.slot_leaves[s] << " leaves";
  EXPECT_EQ(w.outside, 0u) << "vertex coordinates outside their leaf's rounded cell";
  EXPECT_EQ(w.cuts, tree.cut_nodes);
  EXPECT_EQ(w.pointers, tree.pointer_slots);
  EXPECT_EQ(w.leaves, tree.leaves);
  EXPECT_EQ(w.empty_leaves, tree.empty_leaves);
  EXPECT_EQ(w.max_depth, tree.max_depth);
  EXPECT_LE(tree.max_depth, gpu::kLooseKdMaxDepth);
  EXPECT_LE(tree.max_leaf_triangles, gpu::kLooseKdMaxLeafTriangles);
  EXPECT_EQ(tree.nodes.size(), tree.blocks << tree.block_levels);
  EXPECT_EQ(tree.flags.size(), tree.nodes.size());
}

TEST(LooseKdTree, PartitionsTheTrianglesIntoLeavesWhoseCellsHoldThem) {
  expectPartitionInsideCells(scenes().cornell_tree, scenes().cornell);
  expectPartitionInsideCells(scenes().chamber_tree, scenes().chamber);
  // The chamber is big enough for the tree to need pointers, several blocks and real depth.
  EXPECT_GT(scenes().chamber_tree.pointer_slots, 0u);
  EXPECT_GT(scenes().chamber_tree.max_depth, gpu::kLooseKdBlockLevels);
}

TEST(LooseKdTree, BuildsTheSameWordsEveryTime) {
  const LooseKdTree again = buildLooseKdTree(scenes().chamber);
  EXPECT_EQ(again.nodes, scenes().chamber_tree.nodes);
  EXPECT_EQ(again.flags, scenes().chamber_tree.flags);
  EXPECT_EQ(again.triangle_order, scenes().chamber_tree.triangle_order);
}

TEST(LooseKdTree, CpuTraversalFindsTheBruteForceHit) {
  expectCpuAgreesWithBruteForce(scenes().cornell, scenes().cornell_tree,
                                test::randomCastRays(scenes().cornell, 2000, 1));
  expectCpuAgreesWithBruteForce(scenes().chamber, scenes().chamber_tree,
                                test::randomCastRays(scenes().chamber, 2000, 2));
}

TEST(LooseKdTree, CpuTraversalFindsTheBruteForceHitAlongAxesAndInCutPlanes) {
  expectCpuAgreesWithBruteForce(scenes().cornell, scenes().cornell_tree,
                                axisRays(scenes().cornell, scenes().cornell_tree, 1000, 3));
  expectCpuAgreesWithBruteForce(scenes().chamber, scenes().chamber_tree,
                                axisRays(scenes().chamber, scenes().chamber_tree, 1000, 4));
}

TEST(LooseKdTree, OtherBlockSizesPackTheSameTree) {
  // The block arithmetic is the tree's own: two levels (a pointer under every cut but the
  // block's root) and six give the same hits.
  for (int levels : {2, 6}) {
    LooseKdTreeSettings settings;
    settings.block_levels = levels;
    const LooseKdTree tree = buildLooseKdTree(scenes().chamber, settings);
    EXPECT_EQ(tree.cut_nodes, scenes().chamber_tree.cut_nodes);
    EXPECT_EQ(tree.triangle_order, scenes().chamber_tree.triangle_order);
    expectPartitionInsideCells(tree, scenes().chamber);
    expectCpuAgreesWithBruteForce(scenes().chamber, tree,
                                  test::randomCastRays(scenes().chamber, 300, 5));
  }
}

TEST(LooseKdTree, KeepsLeavesWithinTheDepthBound) {
  // The default build goes deeper than 8, so a bound of 8 forces median splits near it.
  ASSERT_GT(scenes().chamber_tree.max_depth, 8);
  LooseKdTreeSettings settings;
  settings.max_depth = 8;
  const LooseKdTree tree = buildLooseKdTree(scenes().chamber, settings);
  EXPECT_LE(tree.max_depth, 8);
  expectPartitionInsideCells(tree, scenes().chamber);
  expectCpuAgreesWithBruteForce(scenes().chamber, tree,
                                test::randomCastRays(scenes().chamber, 300, 6));
  // 3 400 triangles cannot fit leaves of 255 within 3 levels.
  settings.max_depth = 3;
  EXPECT_THROW(buildLooseKdTree(scenes().chamber, settings), std::invalid_argument);
}

// A triangle tilted out of every coordinate plane, so that its bounds have depth along every axis.
// The ray from (0.25, 0.25, 1) straight down meets it at z = 0.125, t = 0.875.
std::vector<glm::vec3> tiltedTriangle() {
  return {{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.3f}, {0.0f, 1.0f, 0.2f}};
}
constexpr float kTiltedHitT = 0.875f;

TEST(LooseKdTree, SplitsAtTheMedianACellTooBigForALeaf) {
  // 600 copies of one triangle: no cut separates them (SAH keeps the cell), but a leaf holds at
  // most 255, so the cell is split at the median until it fits.
  scene::Scene copies;
  scene::Mesh mesh;
  mesh.positions = tiltedTriangle();
  for (int i = 0; i < 600; ++i) mesh.triangles.push_back({0u, 1u, 2u});
  copies.meshes.push_back(mesh);
  const IvmTriangleSet set = buildIvmTriangles(copies);
  const LooseKdTree tree = buildLooseKdTree(set);
  EXPECT_GT(tree.median_splits, 0u);
  EXPECT_LE(tree.max_leaf_triangles, gpu::kLooseKdMaxLeafTriangles);
  expectPartitionInsideCells(tree, set);
  const gpu::RayCastHit hit = castLooseKdTree(tree, set, ivmRayOrigin(set, {0.25f, 0.25f, 1.0f}),
                                              {0.0f, 0.0f, -1.0f}, 0.0f, gpu::kRayInfinity);
  EXPECT_NE(hit.triangle, gpu::kNoRayTriangle);
  EXPECT_NEAR(hit.t, kTiltedHitT, 1e-5f);
}

TEST(LooseKdTree, HitsAndMissesASceneOfOneTriangle) {
  scene::Scene one;
  scene::Mesh mesh;
  mesh.positions = tiltedTriangle();
  mesh.triangles = {{0u, 1u, 2u}};
  one.meshes.push_back(mesh);
  const IvmTriangleSet set = buildIvmTriangles(one);
  const LooseKdTree tree = buildLooseKdTree(set);
  EXPECT_EQ(tree.cut_nodes, 0u);
  EXPECT_EQ(tree.leaves, 1u);
  EXPECT_EQ(tree.blocks, 1u);
  const glm::vec3 o = ivmRayOrigin(set, {0.25f, 0.25f, 1.0f});
  const gpu::RayCastHit hit =
      castLooseKdTree(tree, set, o, {0.0f, 0.0f, -1.0f}, 0.0f, gpu::kRayInfinity);
  EXPECT_EQ(hit.triangle, 0u);
  EXPECT_NEAR(hit.t, kTiltedHitT, 1e-5f);
  const gpu::RayCastHit miss =
      castLooseKdTree(tree, set, o, {0.0f, 0.0f, 1.0f}, 0.0f, gpu::kRayInfinity);
  EXPECT_EQ(miss.triangle, gpu::kNoRayTriangle);
  EXPECT_EQ(miss.t, gpu::kRayInfinity);
  // Beyond t_max, and before t_min: no hit.
  EXPECT_EQ(castLooseKdTree(tree, set, o, {0.0f, 0.0f, -1.0f}, 0.0f, 0.8f).triangle,
            gpu::kNoRayTriangle);
  EXPECT_EQ(castLooseKdTree(tree, set, o, {0.0f, 0.0f, -1.0f}, 0.9f, gpu::kRayInfinity).triangle,
            gpu::kNoRayTriangle);
}

TEST(LooseKdTree, RejectsSettingsOutOfRange) {
  const IvmTriangleSet& set = scenes().cornell;
  LooseKdTreeSettings s;
  s.max_leaf_triangles = 256;
  EXPECT_THROW(buildLooseKdTree(set, s), std::invalid_argument);
  s = {};
  s.block_levels = 1;
  EXPECT_THROW(buildLooseKdTree(set, s), std::invalid_argument);
  s = {};
  s.max_depth = gpu::kLooseKdMaxDepth + 1;
  EXPECT_THROW(buildLooseKdTree(set, s), std::invalid_argument);
  s = {};
  s.intersection_cost = 0.0f;
  EXPECT_THROW(buildLooseKdTree(set, s), std::invalid_argument);
}

class LooseKdTreeGpu : public test::GlTest {};

TEST_F(LooseKdTreeGpu, FindsTheCpuTraversalsHits) {
  // The two scenes, and one triangle (a tree that is a single leaf).
  scene::Scene one;
  scene::Mesh mesh;
  mesh.positions = tiltedTriangle();
  mesh.triangles = {{0u, 1u, 2u}};
  one.meshes.push_back(mesh);
  const IvmTriangleSet single = buildIvmTriangles(one);
  for (const IvmTriangleSet* set : {&scenes().cornell, &scenes().chamber, &single}) {
    const std::unique_ptr<GpuRayStructure> structure = makeGpuRayStructure("loose_kd_tree", *set);
    const auto& gpu_tree = dynamic_cast<const GpuLooseKdTree&>(*structure);
    const LooseKdTree& tree = gpu_tree.tree();
    EXPECT_EQ(gpu_tree.bytes(), tree.bytes() + packRayTriangles(*set, tree.triangle_order).size() *
                                                   sizeof(glm::vec4));
    std::vector<CastRay> rays = test::randomCastRays(*set, 2000, 7);
    const std::vector<CastRay> axes = axisRays(*set, tree, 500, 8);
    rays.insert(rays.end(), axes.begin(), axes.end());
    RayCastPass pass(gpu_tree);
    pass.setRays(rays);
    pass.cast();
    const std::vector<gpu::RayCastHit> hits = pass.hits();
    ASSERT_EQ(hits.size(), rays.size());
    const float tie = kTieFraction * glm::length(set->bounds_max - set->bounds_min);
    int disagreements = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const CastRay& r = rays[i];
      const gpu::RayCastHit cpu =
          castLooseKdTree(tree, *set, r.origin, r.direction, r.t_min, r.t_max);
      if (!test::sameCastHit(cpu, hits[i], tie) && ++disagreements <= 5)
        ADD_FAILURE() << "ray " << i << ": CPU " << cpu.triangle << " at t " << cpu.t << ", GPU "
                      << hits[i].triangle << " at t " << hits[i].t;
    }
    EXPECT_EQ(disagreements, 0) << "of " << rays.size() << " rays";
  }
}

}  // namespace
}  // namespace gib::rt
