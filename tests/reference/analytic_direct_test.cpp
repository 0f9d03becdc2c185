// Direct lighting against closed forms: a Lambertian floor lit by a rectangular area light
// (Lambert's polygon formula), a spot light, a directional light and a constant sky. With the
// path class limited to one bounce the floor's radiance is ρ/π · E exactly.
#include "reference/path_tracer.h"
#include "scene/mesh_builder.h"
#include "support/render_statistics.h"
#include "support/statistical_test.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <numbers>

namespace gib::ref {
namespace {

constexpr float kAlbedo = 0.5f;
constexpr double kPi = std::numbers::pi;
constexpr std::uint32_t kSamples = 20000;  // paths of each estimate that carries noise

// A correct path tracer fails one of this file's statistical tests with probability 1%: the area
// light's five points and the constant sky. The delta lights' estimates have no noise.
constexpr test::TestFamily kFamily(0.01, 5 + 1);

// A 40 × 40 floor at y = 0 facing up; nothing else unless a test adds it.
scene::Scene makeFloorScene() {
  scene::Scene s;
  s.name = "floor";
  scene::Material floor;
  floor.name = "floor";
  floor.diffuse = scene::Rgb(kAlbedo);
  s.materials.push_back(floor);
  scene::Mesh mesh;
  mesh.name = "floor";
  scene::appendQuad(mesh, {-20, 0, -20}, {-20, 0, 20}, {20, 0, 20}, {20, 0, -20});
  s.meshes.push_back(mesh);
  s.camera.position = {0, 5, 0};
  s.camera.look_at = {0, 0, 0};
  s.camera.up = {0, 0, 1};
  return s;
}

// Irradiance at `p` (normal +y) from a Lambertian polygon of radiance L: Lambert's formula
// E = L/2 · |Σ γᵢ (n · Γᵢ)|, γᵢ the angle edge i subtends at p, Γᵢ the unit normal of the plane
// through p and the edge.
double polygonIrradiance(const std::vector<glm::dvec3>& polygon, glm::dvec3 p, double radiance) {
  const glm::dvec3 n(0, 1, 0);
  double sum = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    glm::dvec3 a = glm::normalize(polygon[i] - p);
    glm::dvec3 b = glm::normalize(polygon[(i + 1) % polygon.size()] - p);
    double gamma = std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
    sum += gamma * glm::dot(n, glm::normalize(glm::cross(a, b)));
  }
  return 0.5 * radiance * std::abs(sum);
}

// The floor's radiance at `p` seen from straight above.
test::MeanEstimate estimateFloorRadiance(const PathTracer& tracer, glm::vec3 p,
                                         std::uint32_t samples, std::uint32_t pixel_id) {
  return test::estimateRayRadiance(tracer, p + glm::vec3(0, 0.25f, 0), {0, -1, 0}, samples,
                                   pixel_id);
}

TEST(AnalyticDirect, RectangularAreaLightMatchesLambertsFormula) {
  scene::Scene s = makeFloorScene();
  scene::Material lamp;
  lamp.name = "lamp";
  lamp.diffuse = scene::Rgb(0.0f);
  lamp.emission = scene::Rgb(2.0f);
  s.materials.push_back(lamp);
  // A 1.0 × 0.6 rectangle at height 1, wound so that it emits downwards.
  std::vector<glm::vec3> corners = {
      {0.5f, 1, -0.3f}, {0.5f, 1, 0.3f}, {-0.5f, 1, 0.3f}, {-0.5f, 1, -0.3f}};
  scene::Mesh light;
  light.name = "light";
  light.material = 1;
  scene::appendQuad(light, corners[0], corners[1], corners[2], corners[3]);
  s.meshes.push_back(light);

  // Direct lighting only, without the emitter seen directly.
  const PathTracer tracer(s, PathClass{1, 1});
  std::vector<glm::dvec3> polygon(corners.begin(), corners.end());
  const std::vector<glm::vec3> points = {
      {0, 0, 0}, {0.4f, 0, 0.2f}, {1.5f, 0, 0.3f}, {-3, 0, 2}, {0.7f, 0, -0.6f}};
  for (std::size_t i = 0; i < points.size(); ++i) {
    double expected = kAlbedo / kPi * polygonIrradiance(polygon, points[i], 2.0);
    test::MeanEstimate e = estimateFloorRadiance(tracer, points[i], kSamples, std::uint32_t(i));
    EXPECT_TRUE(kFamily.tTest(e.mean, expected, e.standard_error, kSamples - 1)) << "point " << i;
    EXPECT_LT(e.standard_error, 0.02 * expected) << "the estimate should be informative";
  }
}

TEST(AnalyticDirect, SpotLightFollowsInverseSquareAndFalloff) {
  scene::Scene s = makeFloorScene();
  scene::SpotLight spot;
  spot.position = {0, 2, 0};
  spot.direction = {0, -1, 0};
  spot.intensity = scene::Rgb(10.0f);
  spot.cone_angle_deg = 50;
  spot.falloff_exponent = 3;
  s.spot_lights.push_back(spot);
  const PathTracer tracer(s, PathClass{1, 1});
  for (glm::vec3 p : {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0.5f), glm::vec3(-1.2f, 0, -1.0f),
                      glm::vec3(3, 0, 0)}) {
    glm::vec3 d = p - spot.position;
    double dist = glm::length(d);
    double cos_axis = -d.y / dist;  // angle to the spot's axis (straight down)
    double cos_surface = cos_axis;  // the floor's normal is the axis reversed
    bool inside = cos_axis >= std::cos(glm::radians(double(spot.cone_angle_deg)));
    double irradiance = inside ? 10.0 * std::pow(cos_axis, 3) * cos_surface / (dist * dist) : 0;
    test::MeanEstimate e = estimateFloorRadiance(tracer, p, 16, 0);
    // A delta light with one bounce is noise-free: only float rounding separates the two.
    EXPECT_NEAR(e.mean, kAlbedo / kPi * irradiance, 1e-5) << "point " << p.x << "," << p.z;
  }
}

TEST(AnalyticDirect, DirectionalLightGivesIrradianceTimesCosine) {
  scene::Scene s = makeFloorScene();
  scene::DirectionalLight sun;
  sun.direction = glm::normalize(glm::vec3(1, -2, 0.5f));
  sun.irradiance = scene::Rgb(3.0f);
  s.directional_lights.push_back(sun);
  const PathTracer tracer(s, PathClass{1, 1});
  test::MeanEstimate e = estimateFloorRadiance(tracer, {0.3f, 0, 0.1f}, 16, 0);
  EXPECT_NEAR(e.mean, kAlbedo / kPi * 3.0 * -sun.direction.y, 1e-5);
}

TEST(AnalyticDirect, ConstantSkyGivesAlbedoTimesSkyRadiance) {
  scene::Scene s = makeFloorScene();
  s.sky_radiance = scene::Rgb(0.8f);
  const PathTracer tracer(s, PathClass{1, 1});
  // E = π L on an unoccluded plane, so L_out = ρ/π · π L = ρ L.
  test::MeanEstimate e = estimateFloorRadiance(tracer, {0, 0, 0}, kSamples, 0);
  EXPECT_TRUE(kFamily.tTest(e.mean, kAlbedo * 0.8, e.standard_error, kSamples - 1, 1e-6));
}

}  // namespace
}  // namespace gib::ref
