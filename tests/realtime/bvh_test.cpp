// The BVH of the ray-casting table (realtime/ray_casting/bvh.h): its tree is a partition of the
// triangles into leaves under boxes that hold them, built the same way every time and within the
// stack's depth; its CPU traversal finds the brute force's closest hit, rays along the axes and
// along box faces included; the GPU's traversal finds the CPU traversal's.
#include "realtime/ray_casting/bvh.h"

#include "common/input_error.h"
#include "common/splitmix.h"
#include "realtime/ray_casting/hit_comparison.h"
#include "realtime/ray_casting/ray_cast_pass.h"
#include "realtime/ray_casting/ray_structures.h"
#include "scene/builtin_scenes.h"
#include "support/cast_rays.h"
#include "support/gl_test_context.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <bit>
#include <cmath>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

namespace gib::rt {
namespace {

// Two casts agree when they name the same triangle, or when both hit and their t differ by at
// most the tie distance of hit_comparison.h (10⁻⁵ of the scene's diagonal): two triangles that
// meet where the ray crosses (a shared edge, a corner) tie within the IVM test's rounding, and
// which one a traversal meets first decides the winner. Stricter than the comparison with Embree:
// a hit against a miss is never a tie here, since every cast runs the same triangle test.
float tie(const IvmTriangleSet& set) {
  return float(tieDistance(set));
}

struct Scenes {
  IvmTriangleSet cornell = buildIvmTriangles(scene::loadScene("cornell"));
  // Detail 1 (about 3 400 triangles) keeps the brute force and llvmpipe quick.
  IvmTriangleSet chamber = buildIvmTriangles(scene::loadScene("chamber", {"detail=1"}));
};

const Scenes& scenes() {
  static const Scenes s;
  return s;
}

float diagonal(const IvmTriangleSet& set) {
  return glm::length(set.bounds_max - set.bounds_min);
}

// Rays along the six axis directions (the other two components exactly 0, so 1/d needs the
// guard), from origins that lie exactly on box faces of the tree: every node's box bounds on
// one axis, the ray running along that face.
std::vector<CastRay> faceRays(const IvmTriangleSet& set, const Bvh& bvh, int count,
                              std::uint64_t seed) {
  std::vector<CastRay> rays;
  std::uint64_t state = seed;
  const std::size_t boxes = bvh.nodeCount() * 2;
  for (int i = 0; i < count; ++i) {
    const std::size_t box = std::size_t(test::unitUniform(state) * double(boxes));
    // Box k of the array is texels 2k (minimum, reference) and 2k + 1 (maximum).
    if (std::bit_cast<std::uint32_t>(bvh.nodes[2 * box].w) == gpu::kBvhEmptyReference) continue;
    const glm::vec4& bound = bvh.nodes[2 * box + std::size_t(i % 2)];  // min or max corner
    const int face_axis = i % 3;
    const int along = (face_axis + 1 + (i / 3) % 2) % 3;
    // Braces: evaluated in order, so the rays are the same on every compiler.
    const glm::vec3 f{float(test::unitUniform(state)), float(test::unitUniform(state)),
                      float(test::unitUniform(state))};
    CastRay ray;
    ray.origin = set.bounds_min + f * (set.bounds_max - set.bounds_min);
    ray.origin[face_axis] = bound[face_axis];
    ray.direction = glm::vec3(0.0f);
    ray.direction[along] = (i / 6) % 2 == 0 ? 1.0f : -1.0f;
    rays.push_back(ray);
  }
  return rays;
}

// Every ray's expected and actual hits agree; the first disagreements are printed.
template <typename Expected, typename Actual>
void expectAgreement(const std::vector<CastRay>& rays, float tie, Expected expected,
                     Actual actual) {
  int disagreements = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const gpu::RayCastHit e = expected(i), a = actual(i);
    if (test::sameCastHit(e, a, tie)) continue;
    if (++disagreements <= 5)
      ADD_FAILURE() << "expected " << test::describeCast(rays[i], e) << ", got "
                    << test::describeCast(rays[i], a);
  }
  EXPECT_EQ(disagreements, 0) << "of " << rays.size() << " rays";
}

void expectCpuAgreesWithBruteForce(const IvmTriangleSet& set, const Bvh& bvh,
                                   const std::vector<CastRay>& rays) {
  expectAgreement(
      rays, tie(set),
      [&](std::size_t i) {
        return castBruteForce(set, rays[i].origin, rays[i].direction, rays[i].t_min, rays[i].t_max);
      },
      [&](std::size_t i) {
        return castBvh(bvh, set, rays[i].origin, rays[i].direction, rays[i].t_min, rays[i].t_max);
      });
}

// What a walk of the packed tree finds: each leaf's slots, checked against every box above.
struct TreeWalk {
  const IvmTriangleSet& set;
  const Bvh& bvh;
  std::vector<int> times_in_a_leaf = std::vector<int>(set.size(), 0);
  std::size_t inner = 0, leaves = 0, boxes_not_containing = 0;
  int depth = 0, largest_leaf = 0;

  // The slots under a reference, `level` inner nodes above it.
  std::vector<std::uint32_t> walk(std::uint32_t reference, int level) {
    std::vector<std::uint32_t> slots;
    if (gpu::bvhIsLeaf(reference)) {
      const std::uint32_t first = gpu::bvhLeafFirst(reference);
      const std::uint32_t count = gpu::bvhLeafCount(reference);
      if (count > 0) ++leaves;
      largest_leaf = std::max(largest_leaf, int(count));
      for (std::uint32_t s = first; s < first + count; ++s) {
        slots.push_back(s);
        ++times_in_a_leaf.at(bvh.triangle_order.at(s));
      }
      return slots;
    }
    ++inner;
    depth = std::max(depth, level + 1);
    for (int child = 0; child < 2; ++child) {
      const glm::vec4 lo = bvh.nodes[reference * gpu::kBvhNodeTexels + 2 * child];
      const glm::vec4 hi = bvh.nodes[reference * gpu::kBvhNodeTexels + 2 * child + 1];
      const std::vector<std::uint32_t> below = walk(std::bit_cast<std::uint32_t>(lo.w), level + 1);
      for (std::uint32_t s : below) {
        const IvmTriangle& t = set.triangles[bvh.triangle_order[s]];
        for (const glm::vec3& v : {t.a, t.b, t.c})
          if (glm::any(glm::lessThan(v, glm::vec3(lo))) ||
              glm::any(glm::greaterThan(v, glm::vec3(hi))))
            ++boxes_not_containing;
      }
      slots.insert(slots.end(), below.begin(), below.end());
    }
    return slots;
  }
};

TEST(BvhBuild, PutsEveryTriangleInExactlyOneLeafUnderBoxesThatContainIt) {
  for (const IvmTriangleSet* set : {&scenes().cornell, &scenes().chamber}) {
    const Bvh bvh = buildBvh(*set);
    ASSERT_EQ(bvh.triangle_order.size(), set->size());
    TreeWalk walk{*set, bvh};
    const std::vector<std::uint32_t> slots = walk.walk(gpu::kBvhRootReference, 0);
    EXPECT_EQ(slots.size(), set->size());
    for (std::size_t t = 0; t < set->size(); ++t)
      EXPECT_EQ(walk.times_in_a_leaf[t], 1) << "triangle " << t;
    EXPECT_EQ(walk.boxes_not_containing, 0u);
    // The statistics describe the tree the walk found, and the tree is every node it holds.
    EXPECT_EQ(walk.inner, bvh.inner_nodes);
    EXPECT_EQ(bvh.inner_nodes, bvh.nodeCount());
    EXPECT_EQ(walk.leaves, bvh.leaves);
    EXPECT_EQ(walk.depth, bvh.max_depth);
    EXPECT_EQ(walk.largest_leaf, bvh.max_leaf_size);
    EXPECT_LE(bvh.max_leaf_size, BvhSettings{}.max_leaf_size);
    EXPECT_LE(bvh.max_depth, gpu::kBvhStackSize);
    // A binary tree with every inner node full: one leaf more than inner nodes.
    EXPECT_EQ(bvh.leaves, bvh.inner_nodes + 1);
    EXPECT_EQ(bvh.bytes(), bvh.inner_nodes * 64);
  }
}

TEST(BvhBuild, IsTheSameBitsOnEveryBuild) {
  const IvmTriangleSet& set = scenes().chamber;
  const Bvh a = buildBvh(set), b = buildBvh(set);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  EXPECT_EQ(std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(glm::vec4)), 0);
  EXPECT_EQ(a.triangle_order, b.triangle_order);
  EXPECT_EQ(a.sah_cost, b.sah_cost);
}

TEST(BvhBuild, SplitsAtTheMedianWhereTheSahWouldExceedTheDepthBound) {
  const IvmTriangleSet& set = scenes().chamber;
  const Bvh free = buildBvh(set);
  BvhSettings bounded;
  // 3 400 triangles at 4 a leaf need 10 levels of median splits; the SAH tree is deeper.
  bounded.max_depth = 11;
  ASSERT_GT(free.max_depth, bounded.max_depth) << "the test needs an SAH tree deeper than 11";
  const Bvh bvh = buildBvh(set, bounded);
  EXPECT_LE(bvh.max_depth, bounded.max_depth);
  TreeWalk walk{set, bvh};
  EXPECT_EQ(walk.walk(gpu::kBvhRootReference, 0).size(), set.size());
  EXPECT_EQ(walk.boxes_not_containing, 0u);
  expectCpuAgreesWithBruteForce(set, bvh, test::randomCastRays(set, 500, 11));
}

TEST(BvhBuild, RefusesSettingsOutsideTheirRanges) {
  const IvmTriangleSet& set = scenes().cornell;
  const auto refused = [&](BvhSettings s) {
    try {
      buildBvh(set, s);
    } catch (const InputError&) {
      return true;
    }
    return false;
  };
  EXPECT_TRUE(refused({.max_leaf_size = 0}));
  EXPECT_TRUE(refused({.max_leaf_size = gpu::kBvhMaxLeafSize + 1}));
  EXPECT_TRUE(refused({.bins = 1}));
  EXPECT_TRUE(refused({.max_depth = gpu::kBvhStackSize + 1}));
  EXPECT_TRUE(refused({.max_depth = 1}));  // the Cornell box needs more than one leaf of 4
  EXPECT_FALSE(refused({.max_leaf_size = gpu::kBvhMaxLeafSize, .bins = 2}));
}

TEST(BvhCast, FindsTheBruteForceHitOnRandomRays) {
  for (const IvmTriangleSet* set : {&scenes().cornell, &scenes().chamber}) {
    const Bvh bvh = buildBvh(*set);
    expectCpuAgreesWithBruteForce(*set, bvh, test::randomCastRays(*set, 2000, 7));
    // Within a segment: t_min and t_max cut hits off as the brute force cuts them.
    std::vector<CastRay> segments = test::randomCastRays(*set, 500, 8);
    for (CastRay& ray : segments) {
      ray.t_min = 0.1f * diagonal(*set);
      ray.t_max = 0.4f * diagonal(*set);
    }
    expectCpuAgreesWithBruteForce(*set, bvh, segments);
  }
}

TEST(BvhCast, FindsTheBruteForceHitAlongAxesAndBoxFaces) {
  for (const IvmTriangleSet* set : {&scenes().cornell, &scenes().chamber}) {
    const Bvh bvh = buildBvh(*set);
    const std::vector<CastRay> rays = faceRays(*set, bvh, 1000, 5);
    ASSERT_GT(rays.size(), 900u);
    expectCpuAgreesWithBruteForce(*set, bvh, rays);
  }
}

TEST(BvhCast, HitsAndMissesASceneOfOneTriangle) {
  scene::Scene one;
  scene::Mesh mesh;
  // Tilted, so that its bounds have depth along every axis.
  mesh.positions = {{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.5f}, {0.0f, 1.0f, 0.25f}};
  mesh.triangles = {{0u, 1u, 2u}};
  one.meshes.push_back(mesh);
  const IvmTriangleSet set = buildIvmTriangles(one);
  const Bvh bvh = buildBvh(set);
  EXPECT_EQ(bvh.inner_nodes, 1u);
  EXPECT_EQ(bvh.leaves, 1u);
  EXPECT_EQ(bvh.max_depth, 1);
  const glm::vec3 o = ivmRayOrigin(set, {0.25f, 0.25f, 1.0f});
  const gpu::RayCastHit hit = castBvh(bvh, set, o, {0.0f, 0.0f, -1.0f}, 0.0f, gpu::kRayInfinity);
  EXPECT_EQ(hit.triangle, 0u);
  EXPECT_NEAR(hit.t, 0.8125f, 1e-5f);  // the plane z = x/2 + y/4 at (1/4, 1/4)
  const gpu::RayCastHit miss = castBvh(bvh, set, o, {0.0f, 0.0f, 1.0f}, 0.0f, gpu::kRayInfinity);
  EXPECT_EQ(miss.triangle, gpu::kNoRayTriangle);
  EXPECT_EQ(miss.t, gpu::kRayInfinity);
  // Beside the triangle, straight down: the root's empty second child is never entered.
  const gpu::RayCastHit beside = castBvh(bvh, set, ivmRayOrigin(set, {0.8f, 0.8f, 1.0f}),
                                         {0.0f, 0.0f, -1.0f}, 0.0f, gpu::kRayInfinity);
  EXPECT_EQ(beside.triangle, gpu::kNoRayTriangle);
  expectCpuAgreesWithBruteForce(set, bvh, test::randomCastRays(set, 200, 3));
}

class BvhGpu : public test::GlTest {};

TEST_F(BvhGpu, FindsTheCpuTraversalsHits) {
  for (const IvmTriangleSet* set : {&scenes().cornell, &scenes().chamber}) {
    const GpuBvh gpu_bvh(*set);
    std::vector<CastRay> rays = test::randomCastRays(*set, 2000, 17);
    const std::vector<CastRay> faces = faceRays(*set, gpu_bvh.bvh(), 500, 19);
    rays.insert(rays.end(), faces.begin(), faces.end());
    RayCastPass pass(gpu_bvh);
    pass.setRays(rays);
    pass.cast();
    const std::vector<gpu::RayCastHit> hits = pass.hits();
    ASSERT_EQ(hits.size(), rays.size());
    expectAgreement(
        rays, tie(*set),
        [&](std::size_t i) {
          return castBvh(gpu_bvh.bvh(), *set, rays[i].origin, rays[i].direction, rays[i].t_min,
                         rays[i].t_max);
        },
        [&](std::size_t i) { return hits[i]; });
  }
}

TEST_F(BvhGpu, IsMadeByNameAndCountsItsBytes) {
  const std::unique_ptr<GpuRayStructure> structure = makeGpuRayStructure("bvh", scenes().cornell);
  ASSERT_EQ(structure->name(), "bvh");
  const auto& gpu_bvh = dynamic_cast<const GpuBvh&>(*structure);
  // The nodes, and the triangles' texels with the slots' indices after them.
  EXPECT_EQ(structure->bytes(),
            gpu_bvh.bvh().bytes() +
                packRayTriangles(scenes().cornell, gpu_bvh.bvh().triangle_order).size() *
                    sizeof(glm::vec4));
  EXPECT_EQ(gpuRayStructureNames().back(), "bvh");
}

}  // namespace
}  // namespace gib::rt
