// `environment_map` (book §4.2.1-4.2.2) against closed forms that do not go through its code: the
// pixel's ray is traced analytically here (spheres and flat quads), and each pixel's expected
// radiance follows from the environment in closed form. A constant environment of radiance L
// gives a Lambertian surface of albedo ρ the radiance ρL and a glossy one seen along its normal
// (ρd + ρs)L, whatever its orientation; an environment L(ω) = max(0, ω·up) gives a Lambertian
// surface tilted by β the irradiance E(β) = (2/3)·((π − β)·cos β + sin β); a perfect mirror shows
// the map's texel in the reflected direction, and a glass of index 1 the texel straight through.
// Also its bad parameters and statistics; every run checks the declared passes and outputs.
#include "realtime/gpu_scene/glossy_exponents.h"
#include "realtime/techniques/environment_map/environment_convolution.h"
#include "realtime/techniques/environment_map/environment_map_technique.h"

#include "scene/camera.h"
#include "scene/environment_map.h"
#include "scene/mesh_builder.h"
#include "scene/path_expression.h"
#include "support/technique_frame.h"
#include "support/test_materials.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

namespace gib::rt {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr int kSize = 48;  // pixels per side: enough pixels on every object, few for llvmpipe

// What a pixel's ray meets first, traced analytically: object k of the test's list, or none.
// Pixels whose ray passes within `margin` of an object's outline are ambiguous (the tessellated
// sphere and the rasteriser may disagree there) and left out.
struct Sphere {
  glm::vec3 centre;
  float radius;
};
struct Quad {
  glm::vec3 centre, u, v;  // centre ± u ± v
};
struct PixelHit {
  int object = -1;  // −1: the ray leaves the scene
  glm::vec3 point{0.0f}, normal{0.0f}, direction{0.0f};
  bool ambiguous = false;
};

class AnalyticScene {
 public:
  void add(Sphere s) { spheres_.push_back(s); }
  void add(Quad q) { quads_.push_back(q); }

  // Objects are numbered spheres first, then quads, in the order added.
  PixelHit trace(const scene::Camera& camera, int x, int y) const {
    const scene::CameraFrame frame = scene::makeCameraFrame(camera, kSize, kSize);
    PixelHit hit;
    hit.direction =
        scene::cameraRayDirection(frame, kSize, kSize, float(x) + 0.5f, float(y) + 0.5f);
    const glm::vec3 o = frame.origin, d = hit.direction;
    float best = 1e30f;
    for (std::size_t k = 0; k < spheres_.size(); ++k) {
      const Sphere& s = spheres_[k];
      const glm::vec3 oc = o - s.centre;
      const float b = glm::dot(oc, d), c = glm::dot(oc, oc) - s.radius * s.radius;
      const float closest = std::sqrt(std::max(0.0f, glm::dot(oc, oc) - b * b));
      if (std::abs(closest - s.radius) < 0.06f * s.radius) hit.ambiguous = true;
      if (b * b - c < 0) continue;
      const float t = -b - std::sqrt(b * b - c);
      if (t > 0 && t < best) {
        best = t;
        hit.object = int(k);
        hit.point = o + t * d;
        hit.normal = glm::normalize(hit.point - s.centre);
      }
    }
    for (std::size_t k = 0; k < quads_.size(); ++k) {
      const Quad& q = quads_[k];
      const glm::vec3 n = glm::normalize(glm::cross(q.u, q.v));
      const float t = glm::dot(q.centre - o, n) / glm::dot(d, n);
      if (!(t > 0 && t < best)) continue;
      const glm::vec3 p = o + t * d - q.centre;
      const float a = glm::dot(p, q.u) / glm::dot(q.u, q.u);
      const float b = glm::dot(p, q.v) / glm::dot(q.v, q.v);
      if (std::abs(a) > 1.0f || std::abs(b) > 1.0f) continue;
      if (std::abs(a) > 0.9f || std::abs(b) > 0.9f) hit.ambiguous = true;
      best = t;
      hit.object = int(spheres_.size() + k);
      hit.point = o + t * d;
      hit.normal = glm::dot(n, d) < 0 ? n : -n;  // the viewer's side
    }
    return hit;
  }

 private:
  std::vector<Sphere> spheres_;
  std::vector<Quad> quads_;
};

void addSphere(scene::Scene& s, AnalyticScene& analytic, const scene::Material& material,
               Sphere sphere) {
  scene::Mesh& mesh = scene::addMeshOfMaterial(s, material.name, material);
  scene::appendSphere(mesh, sphere.centre, sphere.radius, 48, 96, false,
                      scene::SphereShading::kSmooth);
  analytic.add(sphere);
}

// The technique declares that it renders mirrors and glass, which the runner also takes as a need
// (a scene without them is refused): scenes that test diffuse surfaces alone carry a mirror
// behind the camera, which no pixel sees and, with no visibility in §4.2, nothing else sees
// either.
void addHiddenMirror(scene::Scene& s) {
  scene::Mesh& mesh = scene::addMeshOfMaterial(s, "hidden mirror", test::perfectMirrorMaterial());
  scene::appendSphere(mesh, s.camera.position + 2.0f * (s.camera.position - s.camera.look_at), 0.1f,
                      8, 16, false);
}

scene::EnvironmentMap constantMap(scene::Rgb L, int height) {
  std::vector<float> texels;
  for (int i = 0; i < 2 * height * height; ++i) texels.insert(texels.end(), {L.r, L.g, L.b});
  return scene::makeEnvironmentMap(2 * height, height, std::move(texels), "constant");
}

glm::vec3 pixel(const image::Image& image, int x, int y) {
  const float* p = image.pixel(x, y);
  return {p[0], p[1], p[2]};
}

// Emitters and the environment seen directly, one diffuse or glossy bounce, the environment seen
// in a mirror (one vertex) or through a glass (two); not a diffuse surface seen in a mirror (the
// environment stands in for the scene's surfaces), nor more specular vertices.
TEST(EnvironmentMapTechnique, PathClassIsTheSingleBounceOfTheEnvironment) {
  const TechniqueInfo& info = findTechnique("environment_map");
  const auto technique = info.create(parseParameters(info.parameters, {}, "environment_map"));
  const scene::PathExpression paths =
      scene::PathExpression::parse(technique->pathClass().expression);
  using enum scene::PathEvent;
  const auto matches = [&](std::vector<scene::PathEvent> path) { return paths.matches(path); };
  EXPECT_TRUE(matches({kLight, kEye}));
  EXPECT_TRUE(matches({kLight, kDiffuse, kEye}));
  EXPECT_TRUE(matches({kLight, kSpecular, kEye}));
  EXPECT_TRUE(matches({kLight, kSpecular, kSpecular, kEye}));
  EXPECT_FALSE(matches({kLight, kDiffuse, kSpecular, kEye}));
  EXPECT_FALSE(matches({kLight, kSpecular, kSpecular, kSpecular, kEye}));
  EXPECT_FALSE(matches({kLight, kDiffuse, kDiffuse, kEye}));
}

// A constant environment: the irradiance is πL on every normal (the convolution's closed form),
// so a Lambertian sphere has radiance ρL wherever it is seen; a glossy one ρd·L + ρs·L where it is
// seen along its normal (∫ (n+2)/(2π) cosⁿ⁺¹θ dω = 1 over the hemisphere); a perfect mirror and a
// glass of any index show L (F·L + (1 − F)·L); the background is L. Given as a map or as a
// scene's constant sky alike (the technique takes the sky for a constant map).
class ConstantEnvironment : public ::testing::TestWithParam<bool> {};

TEST_P(ConstantEnvironment, GivesTheClosedForms) {
  const scene::Rgb L(0.5f, 1.0f, 2.0f);
  scene::Scene s;
  s.name = "constant environment";
  s.camera.position = {0.0f, 0.5f, 6.0f};
  s.camera.look_at = {0.0f, 0.0f, 0.0f};
  s.camera.vertical_fov_deg = 40.0f;
  AnalyticScene analytic;
  const float rho = 0.7f;
  scene::Material phong = test::lambertMaterial(0.3f);
  phong.name = "phong";
  phong.type = scene::MaterialType::kPhong;
  phong.specular = scene::Rgb(0.5f);
  phong.exponent = 20.0f;
  addSphere(s, analytic, test::lambertMaterial(rho), {{-1.1f, 0.6f, 0.0f}, 0.5f});
  addSphere(s, analytic, phong, {{1.1f, 0.6f, 0.0f}, 0.5f});
  addSphere(s, analytic, test::perfectMirrorMaterial(), {{-1.1f, -0.6f, 0.0f}, 0.5f});
  addSphere(s, analytic, test::glassMaterial(1.5f), {{1.1f, -0.6f, 0.0f}, 0.5f});
  if (GetParam())
    s.environment = constantMap(L, 4);
  else
    s.sky_radiance = L;

  const TechniqueRunResult result = test::renderOneFrame(s, "environment_map", {}, kSize);
  // The irradiance sums are exact for cells wholly above a normal's horizon and clamp the cells
  // it crosses: at 64 source rows they err by 2.6·10⁻⁴ of πL at most (computed over normals on
  // a fine grid, 2026-11-28); float sums of 8192 terms add 10⁻⁵.
  constexpr float kRelative = 2e-3f;
  const float expected[4] = {rho, 0.3f + 0.5f, 1.0f, 1.0f};
  int checked[4] = {0, 0, 0, 0};
  int background = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const PixelHit hit = analytic.trace(s.camera, x, y);
      if (hit.ambiguous) continue;
      const glm::vec3 radiance = pixel(result.image, x, y);
      if (hit.object < 0) {
        EXPECT_EQ(radiance, L) << "background at " << x << ", " << y;
        ++background;
        continue;
      }
      // The glossy closed form holds where the eye looks along the normal.
      if (hit.object == 1 && glm::dot(hit.normal, -hit.direction) < 0.97f) continue;
      const glm::vec3 want = expected[hit.object] * L;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(radiance[c], want[c], kRelative * want[c])
            << "object " << hit.object << " at " << x << ", " << y << " channel " << c;
      ++checked[hit.object];
    }
  for (int k = 0; k < 4; ++k) EXPECT_GE(checked[k], 4) << "object " << k << " barely seen";
  EXPECT_GT(background, kSize * kSize / 4);
}

INSTANTIATE_TEST_SUITE_P(EnvironmentMapTechnique, ConstantEnvironment, ::testing::Bool(),
                         [](const auto& info) { return info.param ? "Map" : "ConstantSky"; });

// L(ω) = max(0, ω·up): a Lambertian quad of albedo ρ whose normal is tilted by β from up receives
//   E(β) = ∫ max(0, ω·up)·max(0, ω·n) dω = (2/3)·((π − β)·cos β + sin β)
// (the overlap of two clamped cosine lobes: 2π/3 at β = 0, 2/3 at β = π/2, 0 at β = π; checked
// against a midpoint sum over the sphere to 10⁻⁵), and has radiance ρ/π·E(β). The map's texels
// hold the cosine at their centres, so the light differs from the smooth one by O(h²).
TEST(EnvironmentMapTechnique, CosineSkyGivesTheClampedCosineIrradiance) {
  constexpr int kMapHeight = 128;
  std::vector<float> texels;
  for (int y = 0; y < kMapHeight; ++y)
    for (int x = 0; x < 2 * kMapHeight; ++x) {
      const float L = std::max(0.0f, std::cos(kPi * (float(y) + 0.5f) / kMapHeight));
      texels.insert(texels.end(), {L, L, L});
    }
  scene::Scene s;
  s.name = "cosine sky";
  s.camera.position = {5.0f, 1.5f, 0.0f};
  s.camera.look_at = {0.0f, 0.0f, 0.0f};
  s.camera.vertical_fov_deg = 50.0f;
  s.environment =
      scene::makeEnvironmentMap(2 * kMapHeight, kMapHeight, std::move(texels), "cosine sky");
  // The map's rotation about +y leaves this light unchanged; a turn tests that it is applied to
  // the lookups and the convolution alike.
  s.environment.rotation_deg = 40.0f;
  const float rho = 0.8f;
  const std::vector<float> tilts = {0.0f, kPi / 4, kPi / 2, 3 * kPi / 4};
  AnalyticScene analytic;
  scene::Mesh& mesh = scene::addMeshOfMaterial(s, "quads", test::lambertMaterial(rho));
  for (std::size_t k = 0; k < tilts.size(); ++k) {
    // Normal (sin β, cos β, 0), facing the camera; side by side along z.
    const float b = tilts[k];
    const Quad q{{0.0f, 0.0f, 1.5f - float(k)},
                 0.4f * glm::vec3(std::cos(b), -std::sin(b), 0.0f),
                 {0.0f, 0.0f, -0.4f}};
    scene::appendQuad(mesh, q.centre - q.u - q.v, q.centre + q.u - q.v, q.centre + q.u + q.v,
                      q.centre - q.u + q.v);
    analytic.add(q);
  }
  addHiddenMirror(s);

  const TechniqueRunResult result = test::renderOneFrame(s, "environment_map", {}, kSize);
  const auto E = [](float b) { return 2.0f / 3.0f * ((kPi - b) * std::cos(b) + std::sin(b)); };
  // Measured against E(0): the sums err by 1.5·10⁻³ of E(β) at most (largest at β = 3π/4,
  // computed as for the constant map), bilinear interpolation of the 32-row map between texel
  // centres by h²/8·max|E''| ≤ 1.3·10⁻³·E(0), the map's piecewise constant cosine by 10⁻⁴.
  const float tolerance = 5e-3f * rho / kPi * E(0.0f);
  std::vector<int> checked(tilts.size(), 0);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const PixelHit hit = analytic.trace(s.camera, x, y);
      if (hit.ambiguous || hit.object < 0) continue;
      const float want = rho / kPi * E(tilts[std::size_t(hit.object)]);
      EXPECT_NEAR(pixel(result.image, x, y).g, want, tolerance)
          << "tilt " << tilts[std::size_t(hit.object)] << " at " << x << ", " << y;
      ++checked[std::size_t(hit.object)];
    }
  for (std::size_t k = 0; k < tilts.size(); ++k) EXPECT_GE(checked[k], 4) << "quad " << k;
}

// A horizontal surface's normal is a pole of the convolved maps: it must read the irradiance of
// straight up, whatever the azimuth, even at the coarsest resolution. A map bright towards +x
// near the zenith (L = 1 + cos φ for θ < 30°, 0.2 elsewhere) makes a row some degrees off the pole
// depend on the azimuth: the bug this guards against read such a row at an azimuth the GPU's
// atan(0, 0) chose (relMSE 0.0245 on the outdoor ground at 8 rows on llvmpipe, 0.0119 on an H200).
TEST(EnvironmentMapTechnique, HorizontalGroundReadsTheZenithsIrradiance) {
  constexpr int kMapHeight = 32;
  std::vector<float> texels;
  double irradiance = 0;  // Σ L·∫cos θ dω over the texels above the horizon, in closed form
  for (int y = 0; y < kMapHeight; ++y)
    for (int x = 0; x < 2 * kMapHeight; ++x) {
      const double theta0 = kPi * y / kMapHeight, theta1 = kPi * (y + 1) / kMapHeight;
      const double phi = 2 * kPi * (x + 0.5) / (2 * kMapHeight);
      const float L = theta1 <= kPi / 6 + 1e-6 ? float(1 + std::cos(phi)) : 0.2f;
      texels.insert(texels.end(), {L, L, L});
      if (theta1 <= kPi / 2 + 1e-6)
        irradiance += L * (2 * kPi / (2 * kMapHeight)) *
                      (std::pow(std::sin(theta1), 2) - std::pow(std::sin(theta0), 2)) / 2;
    }
  scene::Scene s;
  s.name = "zenith";
  s.camera.position = {0.0f, 2.0f, 2.0f};
  s.camera.look_at = {0.0f, 0.0f, 0.0f};
  s.camera.vertical_fov_deg = 40.0f;
  s.environment = scene::makeEnvironmentMap(2 * kMapHeight, kMapHeight, std::move(texels), "z");
  const float rho = 0.5f;
  scene::Mesh& mesh = scene::addMeshOfMaterial(s, "ground", test::lambertMaterial(rho));
  scene::appendQuad(mesh, {-3, 0, -3}, {-3, 0, 3}, {3, 0, 3}, {3, 0, -3});
  addHiddenMirror(s);
  const TechniqueRunResult result = test::renderOneFrame(
      s, "environment_map", {"irradiance_resolution=8", "source_resolution=32"}, kSize);
  // The sums are exact for every cell above the horizon (none crosses it: 32 rows put a boundary
  // there), so only float rounding separates the pixel from ρ/π·E.
  const float want = float(rho / kPi * irradiance);
  for (int y = kSize / 2; y < kSize; y += 5)
    for (int x = 0; x < kSize; x += 5)
      EXPECT_NEAR(pixel(result.image, x, y).g, want, 1e-3f * want) << x << ", " << y;
}

// A map of distinct texels, turned and scaled: a flat perfect mirror shows exactly the texel its
// reflected ray falls in, a glass sphere of index 1 (exact Fresnel: F = 0, T = V) the texel
// straight through it, and the background the texel of the camera ray, as
// scene::EnvironmentMap::radiance gives them to the reference. Rays within a thousandth of a
// texel of a texel's edge are left out: the GPU's direction there may round to the neighbour.
TEST(EnvironmentMapTechnique, PerfectMirrorShowsTheTexelOfTheReflectedRay) {
  constexpr int kMapHeight = 8;
  std::vector<float> texels;
  for (int y = 0; y < kMapHeight; ++y)
    for (int x = 0; x < 2 * kMapHeight; ++x)
      texels.insert(texels.end(), {float(x + 1), float(y + 1), float((x * 7 + y * 3) % 11)});
  scene::Scene s;
  s.name = "mirror";
  s.camera.position = {0.0f, 2.0f, 4.0f};
  s.camera.look_at = {0.0f, 0.0f, 0.0f};
  s.camera.vertical_fov_deg = 60.0f;
  s.environment =
      scene::makeEnvironmentMap(2 * kMapHeight, kMapHeight, std::move(texels), "texels");
  s.environment.rotation_deg = 30.0f;
  s.environment.intensity = 2.0f;
  AnalyticScene analytic;
  addSphere(s, analytic, test::glassMaterial(1.0f), {{0.8f, 0.6f, 0.5f}, 0.5f});
  const Quad floor{{0.0f, 0.0f, 0.0f}, {1.5f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.5f}};
  scene::Mesh& mesh = scene::addMeshOfMaterial(s, "floor mirror", test::perfectMirrorMaterial());
  scene::appendQuad(mesh, floor.centre - floor.u - floor.v, floor.centre + floor.u - floor.v,
                    floor.centre + floor.u + floor.v, floor.centre - floor.u + floor.v);
  analytic.add(floor);

  const TechniqueRunResult result =
      test::renderOneFrame(s, "environment_map", {"fresnel=exact"}, kSize);
  const auto onTexelEdge = [&](const glm::vec3& world) {
    const glm::vec2 uv = scene::latLongCoordinates(s.environment.toMap(world));
    const glm::vec2 t = uv * glm::vec2(s.environment.width, s.environment.height);
    const glm::vec2 f = t - glm::floor(t);
    return glm::min(f, 1.0f - f).x < 1e-3f || glm::min(f, 1.0f - f).y < 1e-3f;
  };
  int seen[3] = {0, 0, 0};  // background, glass, mirror
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const PixelHit hit = analytic.trace(s.camera, x, y);
      if (hit.ambiguous) continue;
      // The glass of index 1 and the background both show the camera ray's texel.
      const glm::vec3 ray =
          hit.object == 1 ? glm::reflect(hit.direction, hit.normal) : hit.direction;
      if (onTexelEdge(ray)) continue;
      const glm::vec3 want = s.environment.radiance(ray);
      // The mirror's texel exactly; the glass adds F·L(R) with F = 0 up to rounding (1e-15).
      const float tolerance = hit.object == 0 ? 1e-6f * (want.r + want.g + want.b) : 0.0f;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(pixel(result.image, x, y)[c], want[c], tolerance)
            << "object " << hit.object << " at " << x << ", " << y << " channel " << c;
      ++seen[hit.object + 1];
    }
  for (int k = 0; k < 3; ++k) EXPECT_GE(seen[k], 20) << "part " << k;
}

// Statistics: the downsampled environment's cells and the convolved maps' texels (one irradiance
// layer and one glossy layer per distinct Phong exponent), and the irradiance map as an image of
// the maps' size; the prepare time is measured.
TEST(EnvironmentMapTechnique, StatisticsCountTheConvolution) {
  scene::Scene s;
  s.name = "statistics";
  s.camera.position = {0.0f, 0.0f, 3.0f};
  s.camera.look_at = {0.0f, 0.0f, 0.0f};
  s.environment = constantMap(scene::Rgb(1.0f), 4);
  for (float exponent : {10.0f, 50.0f, 10.0f}) {
    scene::Material m = test::lambertMaterial(0.2f);
    m.type = scene::MaterialType::kPhong;
    m.specular = scene::Rgb(0.3f);
    m.exponent = exponent;
    scene::appendSphere(scene::addMeshOfMaterial(s, "glossy", m), glm::vec3(exponent / 50.0f), 0.2f,
                        8, 16, false);
  }
  addHiddenMirror(s);
  EXPECT_EQ(glossyExponents(s), (std::vector<float>{10.0f, 50.0f}));
  const TechniqueRunResult result = test::renderOneFrame(
      s, "environment_map", {"irradiance_resolution=8", "source_resolution=64"}, 16);
  // The map's 4 rows refined to the source's 64: the sums' error is the source's, not the map's.
  EXPECT_EQ(test::statisticNamed(result.statistics, "source_texels"), 128 * 64);
  EXPECT_EQ(test::statisticNamed(result.statistics, "convolved_texels"), 16 * 8 * 3);
  EXPECT_EQ(test::statisticNamed(result.statistics, "texels_summed"), 128 * 64 * 16 * 8 * 3);
  EXPECT_EQ(test::statisticNamed(result.statistics, "glossy_maps"), 2);
  EXPECT_GT(test::statisticNamed(result.statistics, "prepare_convolution_ms"), 0.0);
  ASSERT_EQ(result.auxiliary.size(), 1u);
  EXPECT_EQ(result.auxiliary[0].name, "irradiance_map");
  EXPECT_EQ(result.auxiliary[0].image.width(), 16);
  EXPECT_EQ(result.auxiliary[0].image.height(), 8);
  // E = π·1 everywhere, to the sums' error at 64 source rows (2.6·10⁻⁴).
  for (int y = 0; y < 8; ++y)
    EXPECT_NEAR(result.auxiliary[0].image.pixel(3, y)[1], kPi, 2e-3f * kPi) << "row " << y;
}

// The resampled environment keeps ∫ L dω: each cell is the solid-angle-weighted mean of the
// texels it covers, also where its rows do not divide the map's or refine them.
TEST(EnvironmentMapTechnique, DownsamplingKeepsTheIntegral) {
  std::vector<float> texels;
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 24; ++x) texels.insert(texels.end(), {float(y * y), float(x), 1.0f});
  const scene::EnvironmentMap map = scene::makeEnvironmentMap(24, 12, std::move(texels), "test");
  const scene::Rgb exact = scene::environmentIntegral(map);
  for (int height : {12, 5, 3, 1, 24, 31}) {
    const DownsampledEnvironment down = downsampleEnvironment(map, height);
    ASSERT_EQ(down.height, height);
    glm::dvec3 integral(0.0);
    double solid_angle = 0;
    for (std::size_t i = 0; i < down.radiance.size(); ++i) {
      integral += glm::dvec3(down.radiance[i]) * double(down.cells[i].w);
      solid_angle += down.cells[i].w;
    }
    EXPECT_NEAR(solid_angle, 4 * std::numbers::pi, 1e-5) << height;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(integral[c], exact[c], 1e-5 * exact[c]) << height;
  }
}

TEST(EnvironmentMapTechnique, RefusesParametersOutOfRange) {
  test::expectParametersRefused("environment_map",
                                {"irradiance_resolution=4", "irradiance_resolution=256",
                                 "source_resolution=4", "source_resolution=512", "fresnel=fast"});
}

}  // namespace
}  // namespace gib::rt
