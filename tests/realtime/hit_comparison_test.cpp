// The tie rule of the ray-casting bench (realtime/ray_casting/hit_comparison.h), case by case on
// two triangles that share an edge and a third one behind them: what counts as agreeing, as a tie
// and as each kind of mismatch, and what |Δt| and the barycentric error measure.
#include "realtime/ray_casting/hit_comparison.h"

#include <gtest/gtest.h>

namespace gib {
namespace {

// A unit square in z = 0 split along its diagonal (triangles 0 and 1 share the edge (1,0)–(0,1)),
// and a square at z = −1 behind it (triangles 2 and 3).
scene::Scene twoSquares() {
  scene::Scene s;
  s.materials.push_back({});
  scene::Mesh front;
  front.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  front.triangles = {{0, 1, 2}, {1, 3, 2}};
  scene::Mesh back = front;
  for (glm::vec3& p : back.positions) p.z = -1.0f;
  s.meshes = {front, back};
  return s;
}

struct Case {
  scene::Scene scene = twoSquares();
  rt::IvmTriangleSet set = rt::buildIvmTriangles(scene);
  // Rays straight down −z from (x, y, 1).
  scene::Ray down(float x, float y) const {
    return {glm::vec3(x, y, 1.0f), glm::vec3(0, 0, -1), 0.0f,
            std::numeric_limits<float>::infinity()};
  }
  rt::HitComparison compare(const scene::Ray& ray, scene::RayHit reference,
                            rt::gpu::RayCastHit cast) const {
    const std::vector<scene::Ray> rays = {ray};
    const std::vector<scene::RayHit> r = {reference};
    const std::vector<rt::gpu::RayCastHit> c = {cast};
    return rt::compareHits(scene, set, rays, r, c, 1e-4);
  }
};

scene::RayHit embreeHit(float t, std::uint32_t mesh, std::uint32_t triangle) {
  scene::RayHit h;
  h.t = t;
  h.mesh = mesh;
  h.triangle = triangle;
  return h;
}

TEST(HitComparison, AgreesOnTheSameTriangleAndMeasuresTAndBarycentrics) {
  const Case k;
  // At (0.25, 0.25) on triangle 0 = (0,0),(1,0),(0,1): barycentrics of b and c are 0.25, 0.25.
  const rt::HitComparison c =
      k.compare(k.down(0.25f, 0.25f), embreeHit(1.0f, 0, 0), {1.00002f, 0, 0.25f, 0.2501f});
  EXPECT_EQ(c.mismatches, 0u);
  EXPECT_EQ(c.same_triangle, 1u);
  EXPECT_NEAR(c.max_abs_dt, 2e-5, 1e-6);
  EXPECT_NEAR(c.max_barycentric_error, 1e-4, 1e-6);
}

TEST(HitComparison, CallsADifferentTriangleAtTheSameDistanceATie) {
  const Case k;
  // Through the shared diagonal: Embree says triangle 0, the GPU triangle 1, both at t = 1.
  const rt::HitComparison c =
      k.compare(k.down(0.5f, 0.5f), embreeHit(1.0f, 0, 0), {1.00001f, 1, 0.5f, 0.5f});
  EXPECT_EQ(c.mismatches, 0u);
  EXPECT_EQ(c.ties, 1u);
}

TEST(HitComparison, CallsATriangleBehindAWrongTriangle) {
  const Case k;
  // The GPU went through the front square to the back one (set index 2: mesh 1's first).
  ASSERT_EQ(k.set.indexOf(1, 0), 2u);
  const rt::HitComparison c =
      k.compare(k.down(0.25f, 0.25f), embreeHit(1.0f, 0, 0), {2.0f, 2, 0.25f, 0.25f});
  EXPECT_EQ(c.wrong_triangle, 1u);
  EXPECT_EQ(c.mismatches, 1u);
}

TEST(HitComparison, TiesAFartherHitWhenTheNearerGrazesAnEdge) {
  const Case k;
  // The GPU takes the front square's outer edge (x = 1 − 5·10⁻⁵) where Embree went on to the back
  // square: a silhouette graze, a tie; the same in the middle of the front square is not.
  EXPECT_EQ(
      k.compare(k.down(1.0f - 5e-5f, 0.5f), embreeHit(2.0f, 1, 1), {1.0f, 1, 0.5f, 0.5f}).ties, 1u);
  EXPECT_EQ(k.compare(k.down(0.25f, 0.25f), embreeHit(2.0f, 1, 0), {1.0f, 0, 0.25f, 0.25f})
                .wrong_triangle,
            1u);
}

TEST(HitComparison, TiesAHitAgainstAMissOnlyAtAnEdge) {
  const Case k;
  const rt::gpu::RayCastHit miss = rt::noRayHit();
  // Embree hits the square's outer edge x = 1 (within δ of it); the GPU misses: a tie.
  EXPECT_EQ(k.compare(k.down(1.0f - 5e-5f, 0.5f), embreeHit(1.0f, 0, 1), miss).ties, 1u);
  // Embree hits the middle of triangle 0; the GPU misses: missed.
  EXPECT_EQ(k.compare(k.down(0.25f, 0.25f), embreeHit(1.0f, 0, 0), miss).missed, 1u);
  // The GPU hits next to the outer edge where Embree misses: a tie; in the middle: extra.
  EXPECT_EQ(k.compare(k.down(1.0f + 5e-5f, 0.5f), {}, {1.0f, 1, 0.5f, 0.5f}).ties, 1u);
  EXPECT_EQ(k.compare(k.down(0.25f, 0.25f), {}, {1.0f, 0, 0.25f, 0.25f}).extra, 1u);
  // Both miss: agreement, nothing counted.
  const rt::HitComparison none = k.compare(k.down(3.0f, 3.0f), {}, miss);
  EXPECT_EQ(none.mismatches + none.ties + none.same_triangle, 0u);
}

TEST(HitComparison, TieDistanceIsAFractionOfTheDiagonal) {
  const Case k;
  EXPECT_NEAR(rt::tieDistance(k.set), rt::kTieFraction * std::sqrt(3.0), 1e-9);
}

}  // namespace
}  // namespace gib
