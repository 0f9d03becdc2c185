// The reference's obscurance estimate (reference/obscurance_estimator.h) against known answers: an
// open plane (W = 1 exactly), a point under a parallel plane (closed forms), a closed box under
// ambient occlusion (W = 0 exactly), and the spectral method on a grey scene (α times the scalar).
#include "reference/obscurance_estimator.h"

#include "reference/path_sampler.h"
#include "scene/mesh_builder.h"
#include "support/inward_box.h"
#include "support/statistical_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace gib::ref {
namespace {

using scene::ObscuranceDefinition;
using scene::ObscuranceFalloff;
using scene::ObscuranceMode;

// A correct estimator fails one of this file's statistical tests with probability 1%: the two
// fall-offs at two heights under the parallel plane. The other tests are exact.
constexpr test::TestFamily kFamily(0.01, 4);
constexpr std::uint32_t kRays = 20000;  // rays of each estimate that carries noise
// The deterministic error the noise is not asked to explain: d and ρ in float, the ray's offset.
constexpr double kFloatAllowance = 1e-5;

scene::Material diffuse(float albedo) {
  scene::Material m;
  m.name = "grey";
  m.diffuse = scene::Rgb(albedo);
  return m;
}

// The floor y = 0 (facing up), a square of half-size `half`, and, unless `height` is 0, the
// same square at y = height facing down.
scene::Scene makePlanes(float half, float height, float albedo = 0.5f) {
  scene::Scene s;
  s.name = "planes";
  s.materials = {diffuse(albedo)};
  scene::Mesh mesh;
  scene::appendQuad(mesh, {-half, 0, -half}, {-half, 0, half}, {half, 0, half}, {half, 0, -half});
  if (height > 0)
    scene::appendQuad(mesh, {-half, height, -half}, {half, height, -half}, {half, height, half},
                      {-half, height, half});
  s.meshes = {mesh};
  return s;
}

// The closed box [0, 1]³ with its faces turned inwards.
scene::Scene makeClosedBox() {
  scene::Scene s;
  s.name = "box";
  s.materials = {diffuse(0.5f)};
  scene::Mesh box;
  for (const auto& q : test::inwardBoxFaces(glm::vec3(0), glm::vec3(1)))
    scene::appendQuad(box, q[0], q[1], q[2], q[3]);
  s.meshes = {box};
  return s;
}

// Sample j's direction point, as estimateObscurances draws it.
glm::vec2 rayPoint(std::uint32_t point, std::uint32_t j, std::uint32_t rays) {
  PathSampler sampler(7, point, j, rays);
  sampler.startVertex(0);
  return sampler.get2D(VertexDimension::kDirection);
}

// W at a point h below a parallel plane, c = h/d_max. Directions at cos θ = μ from the normal
// reach the plane at d = h/μ, and dω = 2π dμ over φ, so eq. 10.2 is
// W = (1/π)∫ρ(h/μ) μ 2π dμ = 2∫₀¹ ρ(h/μ) μ dμ. With ρ = 1 for μ < c (d ≥ d_max): for the square
// root, 2∫₀ᶜ μ dμ + 2√c∫_c¹ √μ dμ = c² + (4/3)√c(1 − c^(3/2)) = (4/3)√c − c²/3; for ambient
// occlusion, 2∫₀ᶜ μ dμ = c². Both are 1 for c ≥ 1.
double parallelPlaneObscurance(ObscuranceFalloff falloff, double c) {
  if (c >= 1) return 1;
  return falloff == ObscuranceFalloff::kSqrt ? 4.0 / 3.0 * std::sqrt(c) - c * c / 3.0 : c * c;
}

TEST(ObscuranceEstimator, OpenPlaneIsOpenForEveryRay) {
  const scene::Scene plane = makePlanes(10, 0, 0.3f);
  for (ObscuranceFalloff falloff : {ObscuranceFalloff::kSqrt, ObscuranceFalloff::kAmbientOcclusion})
    for (ObscuranceMode mode : {ObscuranceMode::kScalar, ObscuranceMode::kSpectral}) {
      const ObscuranceEstimator estimator(plane, {falloff, mode, 0.25f});
      // Nothing is above the plane: every ray misses, ρ = 1, and the spectral value is ā (the
      // plane's albedo, the only one there is).
      const glm::vec3 expected =
          mode == ObscuranceMode::kScalar ? glm::vec3(1.0f) : estimator.averageAlbedo();
      EXPECT_NEAR(estimator.averageAlbedo().r, 0.3f, 1e-7f);
      for (std::uint32_t j = 0; j < 1000; ++j) {
        const glm::vec3 w = estimator.sample({1.5f, 0, -2}, {0, 1, 0}, rayPoint(0, j, 1000));
        ASSERT_EQ(w, expected) << "ray " << j;
      }
    }
}

TEST(ObscuranceEstimator, PointUnderAParallelPlaneMatchesTheClosedForm) {
  // d_max is a quarter of the diagonal, about 7.1 for these 20 × 20 planes; rays that hit the
  // upper plane nearer than d_max travel less than d_max sideways, so the planes, 10 to each
  // side of the point, are as good as infinite.
  for (float height : {1.0f, 3.0f}) {
    const scene::Scene planes = makePlanes(10, height);
    for (ObscuranceFalloff falloff :
         {ObscuranceFalloff::kSqrt, ObscuranceFalloff::kAmbientOcclusion}) {
      const ObscuranceEstimator estimator(planes, {falloff, ObscuranceMode::kScalar, 0.25f});
      ASSERT_LE(estimator.maxDistance(), 10.0f);
      const double c = height / estimator.maxDistance();
      const std::vector<ObscurancePoint> points = {{{0, 0, 0}, {0, 1, 0}}};
      const ObscuranceEstimate e = estimateObscurances(estimator, points, kRays, 11).front();
      SCOPED_TRACE(testing::Message()
                   << scene::obscuranceFalloffName(falloff) << " h = " << height << " c = " << c);
      EXPECT_EQ(e.mean.r, e.mean.g);
      EXPECT_TRUE(kFamily.tTest(e.mean.r, parallelPlaneObscurance(falloff, c), e.standard_error.r,
                                kRays - 1, kFloatAllowance));
    }
  }
}

TEST(ObscuranceEstimator, PlaneBeyondMaxDistanceLeavesThePointOpen) {
  // d_max = 0.25 · √(20² + 20² + 8²) ≈ 7.35 < 8: no ray finds the plane nearer than d_max.
  const scene::Scene planes = makePlanes(10, 8);
  for (ObscuranceFalloff falloff :
       {ObscuranceFalloff::kSqrt, ObscuranceFalloff::kAmbientOcclusion}) {
    const ObscuranceEstimator estimator(planes, {falloff, ObscuranceMode::kScalar, 0.25f});
    ASSERT_LT(estimator.maxDistance(), 8.0f);
    for (std::uint32_t j = 0; j < 1000; ++j)
      ASSERT_EQ(estimator.sample({0, 0, 0}, {0, 1, 0}, rayPoint(1, j, 1000)), glm::vec3(1.0f));
  }
}

TEST(ObscuranceEstimator, ClosedBoxIsClosedUnderAmbientOcclusion) {
  // d_max = 1.5 diagonals: every ray hits a wall nearer than that.
  const scene::Scene box = makeClosedBox();
  const ObscuranceEstimator estimator(
      box, {ObscuranceFalloff::kAmbientOcclusion, ObscuranceMode::kScalar, 1.5f});
  const std::vector<ObscurancePoint> points = {{{0.5f, 0, 0.5f}, {0, 1, 0}},
                                               {{0.01f, 0, 0.99f}, {0, 1, 0}},
                                               {{1, 0.3f, 0.7f}, {-1, 0, 0}},
                                               {{0.2f, 0.8f, 0}, {0, 0, 1}}};
  for (const ObscuranceEstimate& e : estimateObscurances(estimator, points, 4096, 3)) {
    EXPECT_EQ(e.mean, glm::dvec3(0.0));
    EXPECT_EQ(e.standard_error, glm::dvec3(0.0));
  }
}

TEST(ObscuranceEstimator, SpectralOfAGreySceneIsItsAlbedoTimesTheScalar) {
  constexpr float kAlbedo = 0.6f;
  const scene::Scene planes = makePlanes(10, 2, kAlbedo);
  const ObscuranceEstimator scalar(planes, {ObscuranceFalloff::kSqrt, ObscuranceMode::kScalar});
  const ObscuranceEstimator spectral(planes, {ObscuranceFalloff::kSqrt, ObscuranceMode::kSpectral});
  // Rays that hit nearer than d_max, farther, and miss: all three branches.
  int near = 0;
  for (std::uint32_t j = 0; j < 4096; ++j) {
    const glm::vec2 u = rayPoint(2, j, 4096);
    const glm::vec3 w_scalar = scalar.sample({0, 0, 0}, {0, 1, 0}, u);
    const glm::vec3 w_spectral = spectral.sample({0, 0, 0}, {0, 1, 0}, u);
    near += w_scalar.r < 1.0f;
    for (int c = 0; c < 3; ++c) ASSERT_FLOAT_EQ(w_spectral[c], kAlbedo * w_scalar[c]) << j;
  }
  EXPECT_GT(near, 0);
  EXPECT_LT(near, 4096);
}

TEST(ObscuranceEstimator, EstimatesDoNotDependOnThreads) {
  const scene::Scene box = makeClosedBox();
  const ObscuranceEstimator estimator(box, {});
  std::vector<ObscurancePoint> points;
  for (int i = 0; i < 40; ++i) points.push_back({{0.025f * i, 0, 0.5f}, {0, 1, 0}});
  const auto one = estimateObscurances(estimator, points, 64, 5, 1);
  const auto two = estimateObscurances(estimator, points, 64, 5, 2);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(one[i].mean, two[i].mean);
    EXPECT_EQ(one[i].standard_error, two[i].standard_error);
  }
  EXPECT_THROW(estimateObscurances(estimator, points, 1, 5), std::invalid_argument);
}

}  // namespace
}  // namespace gib::ref
