// The area-light sampler takes one 2D point for the emitter's choice and the point on it, so a
// stratified point set stays stratified over all emitters together: each triangle gets its share
// of the samples to within two (less than one at each end of its interval of the first
// coordinate), where an independent choice would give a binomial count.
#include "reference/area_light_sampler.h"
#include "reference/path_sampler.h"
#include "reference/rng.h"
#include "scene/mesh_builder.h"
#include "support/statistical_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace gib::ref {
namespace {

// A correct sampler fails this file's one statistical test (its chi-square) with probability 1%.
constexpr test::TestFamily kFamily(0.01, 1);

// Three emitting triangles at y = 1 facing down: a unit right triangle of radiance 1 and a
// 1 × 2 rectangle (two triangles) of radiance 3, so the powers are 0.5 : 3 : 3.
scene::Scene makeLights() {
  scene::Scene s;
  scene::Material dim;
  dim.name = "dim";
  dim.emission = scene::Rgb(1.0f);
  scene::Material bright;
  bright.name = "bright";
  bright.emission = scene::Rgb(3.0f);
  s.materials = {dim, bright};
  scene::Mesh small;
  small.name = "small";
  small.positions = {{-3, 1, 0}, {-2, 1, 0}, {-3, 1, 1}};
  small.triangles = {{0, 1, 2}};
  small.material = 0;
  scene::Mesh rectangle;
  rectangle.name = "rectangle";
  scene::appendQuad(rectangle, {0, 1, 0}, {1, 1, 0}, {1, 1, 2}, {0, 1, 2});
  rectangle.material = 1;
  s.meshes = {small, rectangle};
  return s;
}

// The point the path tracer hands the light sampler at sample i of a pixel (its first scattering
// vertex): every power-of-two prefix of a pixel's samples is a (0,m,2)-net.
glm::vec2 lightPoint(std::uint32_t i, std::uint64_t seed) {
  PathSampler sampler(seed, 0, i, 1);
  sampler.startVertex(1);
  return sampler.get2D(VertexDimension::kLightPoint);
}

TEST(AreaLightSampler, OnePointKeepsTheEmittersShareToWithinTwoSamples) {
  const scene::Scene lights = makeLights();
  const TriangleTable triangles(lights);
  const AreaLightSampler sampler(lights, triangles);
  ASSERT_EQ(triangles.size(), 3u);
  const double share[3] = {0.5 / 6.5, 3.0 / 6.5, 3.0 / 6.5};
  for (std::uint64_t seed : {1u, 2u, 3u})
    for (std::uint32_t n : {16u, 256u, 1024u}) {
      std::vector<int> count(3, 0);
      for (std::uint32_t i = 0; i < n; ++i) ++count[sampler.sample(lightPoint(i, seed)).triangle];
      for (int t = 0; t < 3; ++t)
        EXPECT_LT(std::abs(count[t] - double(n) * share[t]), 2.0)
            << "triangle " << t << " of " << n << " net points, seed " << seed;
    }
}

TEST(AreaLightSampler, PointsAreUniformOverEachEmitterWithTheStatedDensity) {
  // Independent points: counts on a grid over the rectangle and per triangle against the
  // density the sampler states (pdfArea × area), by chi-square.
  const scene::Scene lights = makeLights();
  const TriangleTable triangles(lights);
  const AreaLightSampler sampler(lights, triangles);
  constexpr int kGrid = 8;  // cells of 1/8 × 2/8 over the rectangle, plus one for the triangle
  std::vector<double> observed(kGrid * kGrid + 1, 0.0);
  SampleStream random(5, 0, 0);
  constexpr int kSamples = 200000;
  for (int i = 0; i < kSamples; ++i) {
    const AreaLightSample s = sampler.sample({random.next(), random.next()});
    EXPECT_FLOAT_EQ(s.pdf_area, sampler.pdfArea(s.triangle));
    if (s.point.x < -1) {
      observed.back() += 1;
      continue;
    }
    const int cx = std::min(kGrid - 1, int(s.point.x * kGrid));
    const int cz = std::min(kGrid - 1, int(s.point.z / 2 * kGrid));
    observed[std::size_t(cz * kGrid + cx)] += 1;
  }
  // The rectangle's density per area is pdfArea of either of its triangles; the small one's
  // probability is its pdfArea times its area (0.5).
  const double rectangle_cell = sampler.pdfArea(1) * (2.0 / (kGrid * kGrid)) * kSamples;
  std::vector<double> expected(observed.size(), rectangle_cell);
  expected.back() = sampler.pdfArea(0) * 0.5 * kSamples;
  EXPECT_NEAR(sampler.pdfArea(0) * 0.5, 0.5 / 6.5, 1e-6);
  EXPECT_TRUE(kFamily.chiSquare(observed, expected));
}

}  // namespace
}  // namespace gib::ref
