// The reference's environment light (scene/environment_map.h) against closed forms: a white
// Lambertian sphere under a constant map reflects albedo × L everywhere (a convex object sees the
// whole environment above every point and nothing of itself); a plane tilted by β under the map
// L = max(0, cos θ) receives E(β) = (2/3)((π − β) cos β + sin β); and a small bright spot (a sun)
// lights a plane by its power, with little noise, since the importance sampler finds it.
#include "reference/path_tracer.h"
#include "scene/environment_map.h"
#include "scene/mesh_builder.h"
#include "support/render_statistics.h"
#include "support/statistical_test.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace gib::ref {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr float kAlbedo = 0.8f;
constexpr std::uint32_t kSamples = 20000;

// A correct path tracer fails one of this file's eight tests with probability 1%: three rays at
// the sphere, three tilted planes, the sun, the plane under a roof without occlusion.
constexpr test::TestFamily kFamily(0.01, 3 + 3 + 1 + 1);

template <typename Radiance>
scene::EnvironmentMap greyMap(int height, Radiance radiance) {
  std::vector<float> texels;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < 2 * height; ++x) {
      const glm::vec2 centre{(x + 0.5f) / (2.0f * height), (y + 0.5f) / float(height)};
      for (int c = 0; c < 3; ++c) texels.push_back(float(radiance(x, y, centre)));
    }
  return scene::makeEnvironmentMap(2 * height, height, std::move(texels), "test");
}

scene::Scene sceneUnder(scene::EnvironmentMap map) {
  scene::Scene s;
  s.name = "environment test";
  scene::Material white;
  white.name = "white";
  white.diffuse = scene::Rgb(kAlbedo);
  s.materials.push_back(white);
  s.environment = std::move(map);
  s.camera.look_at = {0, 0, -1};
  return s;
}

// ∫ L(ω) max(0, ω·n) dω of the map's piecewise-constant texels, by the midpoint rule on 8 × 8
// points per texel in (u, v): independent of the sampler, and exact but for the cosine's
// variation within a texel.
double cosineIntegral(const scene::EnvironmentMap& map, const glm::vec3& n) {
  const int rows = 8 * map.height, columns = 8 * map.width;
  double sum = 0;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const glm::vec2 uv{(i + 0.5f) / float(columns), (j + 0.5f) / float(rows)};
      const glm::vec3 d = map.toWorld(scene::latLongDirection(uv));
      const double cosine = glm::dot(d, n);
      if (cosine > 0) sum += map.radiance(d).r * cosine * std::sin(kPi * uv.y);
    }
  return sum * 2 * kPi * kPi / (double(rows) * columns);
}

TEST(EnvironmentLight, WhiteSphereUnderConstantMapReflectsAlbedoTimesRadiance) {
  scene::Scene s = sceneUnder(greyMap(16, [](int, int, glm::vec2) { return 1.0; }));
  scene::appendSphere(s.meshes.emplace_back(), {0, 0, 0}, 1.0f, 12, 24, /*inward=*/false,
                      scene::SphereShading::kFlat);
  const PathTracer tracer(s, PathClass{});
  // Rays from three sides; a ray that misses sees the map itself, exactly.
  const std::vector<glm::vec3> origins = {{0, 0, 4}, {3, 2, 1}, {-1, -3, -2}};
  for (std::uint32_t i = 0; i < origins.size(); ++i) {
    const glm::vec3 towards = glm::normalize(glm::vec3(0.1f, -0.2f, 0.05f) - origins[i]);
    const test::MeanEstimate e =
        test::estimateRayRadiance(tracer, origins[i], towards, kSamples, i);
    EXPECT_TRUE(kFamily.tTest(e.mean, kAlbedo, e.standard_error, e.dof, 1e-5)) << "ray " << i;
  }
  const test::MeanEstimate miss = test::estimateRayRadiance(tracer, {0, 0, 4}, {0, 1, 0}, 4, 9);
  EXPECT_FLOAT_EQ(float(miss.mean), 1.0f);
}

class TiltedPlaneUnderCosineMap : public ::testing::TestWithParam<double> {};

TEST_P(TiltedPlaneUnderCosineMap, ReceivesTheClosedFormIrradiance) {
  const double beta = GetParam();
  // The map L = max(0, cos θ), θ from +y, at each texel's centre, turned about +y (which leaves
  // it unchanged: the closed form does not depend on the rotation).
  scene::EnvironmentMap map = greyMap(
      128, [](int, int, glm::vec2 uv) { return std::max(0.0, std::cos(kPi * double(uv.y))); });
  map.rotation_deg = 25.0f;
  scene::Scene s = sceneUnder(map);
  // A 2 × 2 square through the origin facing n = (sin β, cos β, 0).
  const glm::vec3 n{float(std::sin(beta)), float(std::cos(beta)), 0.0f};
  const glm::vec3 t{0, 0, 1}, b = glm::cross(n, t);
  scene::appendQuad(s.meshes.emplace_back(), -b - t, -b + t, b + t, b - t);
  ASSERT_GT(glm::dot(glm::cross(2.0f * t, 2.0f * b), n), 0.0f) << "the square faces n";
  // Direct light only: ρ/π · E.
  const PathTracer tracer(s, PathClass{1, 1});
  const test::MeanEstimate e = test::estimateRayRadiance(tracer, n, -n, kSamples, 0);
  const double closed_form = 2.0 / 3.0 * ((kPi - beta) * std::cos(beta) + std::sin(beta));
  // The texels hold the cosine at their centres: what that discretisation changes is known, and
  // allowed; noise must explain the rest.
  const double discretisation = std::abs(cosineIntegral(s.environment, n) - closed_form);
  EXPECT_LT(discretisation, 0.01 * closed_form) << "the map approximates max(0, cos θ)";
  EXPECT_TRUE(kFamily.tTest(e.mean, kAlbedo / kPi * closed_form, e.standard_error, e.dof,
                            kAlbedo / kPi * discretisation))
      << "β = " << beta;
  EXPECT_LT(e.standard_error, 0.01 * kAlbedo / kPi * closed_form) << "an informative estimate";
}

INSTANTIATE_TEST_SUITE_P(Angles, TiltedPlaneUnderCosineMap, ::testing::Values(0.0, 1.0, 2.0));

TEST(EnvironmentLight, SunTexelLightsAPlaneByItsPowerWithLittleNoise) {
  // One texel of 20 000 (0.002 sr) on a dim sky of 0.01: the sun holds 99.9% of the light on the
  // plane.
  const scene::EnvironmentMap map =
      greyMap(64, [](int x, int y, glm::vec2) { return x == 40 && y == 20 ? 20000.0 : 0.01; });
  scene::Scene s = sceneUnder(map);
  scene::appendQuad(s.meshes.emplace_back(), {-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1});
  const PathTracer tracer(s, PathClass{1, 1});
  const std::uint32_t samples = 2000;
  const test::MeanEstimate e = test::estimateRayRadiance(tracer, {0, 1, 0}, {0, -1, 0}, samples, 0);
  const double expected = kAlbedo / kPi * cosineIntegral(map, {0, 1, 0});
  EXPECT_TRUE(kFamily.tTest(e.mean, expected, e.standard_error, e.dof, 1e-4 * expected));
  // Uniform sampling of the hemisphere would find the sun in one path of about 3 000 (its solid
  // angle over 2π), most estimates of 2 000 paths missing it; importance sampling errs by under 2%.
  EXPECT_LT(e.standard_error, 0.02 * expected);
}

TEST(EnvironmentLight, WithoutOcclusionAPlaneUnderARoofSeesTheWholeSky) {
  // A plane with a roof 0.5 above it (8 × 8, twice the plane's size), under a constant map of 1:
  // occluded, the centre sees a thin band of sky at the sides; without occlusion (book §4.2.2's
  // v = 1), E = π exactly, so the one-bounce radiance is ρ.
  scene::Scene s = sceneUnder(greyMap(16, [](int, int, glm::vec2) { return 1.0; }));
  scene::appendQuad(s.meshes.emplace_back(), {-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2});
  scene::appendQuad(s.meshes.emplace_back(), {-4, 0.5f, -4}, {4, 0.5f, -4}, {4, 0.5f, 4},
                    {-4, 0.5f, 4});
  const glm::vec3 origin{0, 0.25f, 0}, down{0, -1, 0};
  const PathTracer unoccluded(s, PathClass{1, 1}, false, /*environment_occlusion=*/false);
  const test::MeanEstimate e = test::estimateRayRadiance(unoccluded, origin, down, kSamples, 0);
  EXPECT_TRUE(kFamily.tTest(e.mean, kAlbedo, e.standard_error, e.dof, 1e-5));
  // The roof stops most of that light when it occludes (the sky's band below 7° of the horizon
  // and the roof's own light, which reaches the plane in two bounces, not in this class).
  const PathTracer occluded(s, PathClass{1, 1});
  EXPECT_LT(test::estimateRayRadiance(occluded, origin, down, 1000, 0).mean, 0.2 * kAlbedo);
  // Every path: the roof's underside, lit by the plane, adds its bounces without occlusion too.
  const PathTracer all_paths(s, PathClass{}, false, false);
  EXPECT_GT(test::estimateRayRadiance(all_paths, origin, down, 1000, 0).mean, 1.1 * kAlbedo);
}

}  // namespace
}  // namespace gib::ref
