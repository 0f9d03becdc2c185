// Light transport through mirrors and glass, against known answers: the furnace with a mirror or
// a glass sphere (every pixel exactly 1), the caustic of a glass sphere under a distant light
// (its power on the floor against the value derived from Fresnel and Snell's laws), the light
// tracer against the path tracer on the caustics both can reach, and path classes that split
// every path in two. A correct renderer fails this file's statistical tests with probability 1%.
#include "reference/light_tracer.h"
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/fresnel_shared.h"
#include "scene/mesh_builder.h"
#include "support/render_statistics.h"
#include "support/statistical_test.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gib::ref {
namespace {

using test::imageMean;

constexpr int kFurnaceSize = 12;
constexpr int kFurnaceRenders = 4;  // two objects, with and without light paths
// Per render: every value and the image mean; then the caustic's power, the light and camera
// paths' caustics, and the two path-class sums.
constexpr test::TestFamily kFamily(0.01, kFurnaceRenders*(3 * kFurnaceSize * kFurnaceSize + 1) + 1 +
                                             1 + 2);

TEST(SpecularFurnace, EveryPixelIsOneWithAMirrorOrAGlassSphere) {
  for (const char* object : {"object=mirror", "object=glass"}) {
    const scene::Scene furnace = scene::loadScene("furnace", {object});
    for (LightPaths light_paths : {LightPaths::kAuto, LightPaths::kOff}) {
      RenderSettings settings;
      settings.width = settings.height = kFurnaceSize;
      settings.spp = 256;
      settings.replicas = 8;
      settings.light_paths = light_paths;
      const RenderResult r = renderReference(furnace, settings);
      EXPECT_EQ(r.light_paths, light_paths == LightPaths::kAuto);
      // Per value, Student's t with 7 degrees of freedom (the replicas): the family's bound.
      for (std::size_t i = 0; i < r.mean.data().size(); ++i) {
        const double variance = r.variance.data()[i];
        EXPECT_TRUE(kFamily.tTest(r.mean.data()[i], 1.0, std::sqrt(variance), r.variance_dof, 1e-5))
            << object << ", light paths " << lightPathsName(light_paths) << ", value " << i;
      }
      const test::ImageMean m = imageMean(r);
      EXPECT_TRUE(kFamily.tTest(m.mean, 1.0, m.standard_error, m.dof, 1e-5))
          << object << ", light paths " << lightPathsName(light_paths);
    }
  }
}

// The caustic of a glass sphere (radius R, index n, centre at height h) on the floor under a
// light falling straight down with irradiance E: each ray at distance b from the axis meets the
// sphere at cos θ = √(1 − b²/R²), is reflected with F(θ), and the rest enters; inside, every
// chord meets the surface at the refraction angle, where 1 − F leaves and F stays, so the ray
// leaving after k chords carries (1 − F)²F^(k−1) (unpolarised Fresnel at each interface, the
// renderer's model). Each leaving ray is followed in the meridional plane to the floor; the power
// landing within radius r of the axis is ∫₀ᴿ E·2πb·Σₖ Pₖ(b)·[lands within r] db, integrated here
// by the midpoint rule.
double analyticCausticPower(double radius, double height, double ior, double irradiance,
                            double landing_radius) {
  using Vec = glm::dvec2;
  auto reflect = [](Vec d, Vec n) { return d - 2.0 * glm::dot(d, n) * n; };
  auto refract = [](Vec d, Vec n, double eta) {  // n against d; eta = η(behind)/η(front)
    const double cos_i = -glm::dot(d, n);
    const double sin2_t = (1.0 - cos_i * cos_i) / (eta * eta);
    return d / eta + (cos_i / eta - std::sqrt(std::max(0.0, 1.0 - sin2_t))) * n;
  };
  auto landsWithin = [&](Vec p, Vec d) {
    if (d.y >= 0) return false;
    return std::abs(p.x + d.x * (-p.y / d.y)) <= landing_radius;
  };
  const Vec centre(0.0, height);
  constexpr int kSteps = 200000;
  double power = 0;
  for (int i = 0; i < kSteps; ++i) {
    const double b = radius * (i + 0.5) / kSteps;
    Vec p(b, height + std::sqrt(radius * radius - b * b));
    const Vec d(0.0, -1.0);
    Vec n = (p - centre) / radius;
    const double cos_i = -glm::dot(d, n);
    const double f = scene::fresnelDielectric(float(cos_i), float(ior));
    double share = 0;
    if (landsWithin(p, reflect(d, n))) share += f;
    Vec t = refract(d, n, ior);
    double inside = 1.0 - f;  // power still inside the sphere
    for (int k = 1; k < 60 && inside > 1e-12; ++k) {
      // The chord to the far side; p is put back on the circle and the vectors renormalised, or
      // rounding would grow over the chords.
      p += -2.0 * glm::dot(p - centre, t) * t;
      n = glm::normalize(p - centre);  // outward; t meets it from inside
      p = centre + radius * n;
      const double f_inside = scene::fresnelDielectric(float(glm::dot(t, n)), float(1.0 / ior));
      if (landsWithin(p, refract(t, -n, 1.0 / ior))) share += inside * (1.0 - f_inside);
      inside *= f_inside;
      t = glm::normalize(reflect(t, -n));
    }
    power += irradiance * 2.0 * M_PI * b * (radius / kSteps) * share;
  }
  return power;
}

TEST(Caustic, GlassSpherePowerOnTheFloorMatchesItsAnalyticValue) {
  constexpr float kRadius = 1.0f, kHeight = 2.0f, kIor = 1.5f, kReach = 4.0f;
  scene::Scene s;
  s.name = "caustic";
  scene::Material floor;
  floor.name = "floor";  // black: a particle's first landing on it is all that is measured
  scene::Material glass;
  glass.name = "glass";
  glass.type = scene::MaterialType::kGlass;
  glass.ior = kIor;
  s.materials = {floor, glass};
  scene::Mesh plane;
  plane.name = "floor";
  const float a = kReach * 1.5f;
  scene::appendQuad(plane, {-a, 0, -a}, {-a, 0, a}, {a, 0, a}, {a, 0, -a});
  scene::Mesh sphere;
  sphere.name = "sphere";
  sphere.material = 1;
  scene::appendSphere(sphere, {0, kHeight, 0}, kRadius, 128, 256, false,
                      scene::SphereShading::kSmooth);
  s.meshes = {plane, sphere};
  s.directional_lights.push_back({{0, -1, 0}, scene::Rgb(1.0f)});
  s.camera.position = {0, 3, 8};
  s.camera.look_at = {0, 1, 0};
  scene::validateScene(s);

  const PathTracer tracer(s, PathClass{}, /*light_paths=*/true);
  const LightTracer light_tracer(s, tracer, 16, 16);
  constexpr std::uint32_t kParticles = 1u << 22;
  double sum = 0, sum2 = 0;
  for (std::uint32_t i = 0; i < kParticles; ++i) {
    PathSampler sampler(3, i, 0, 1, SamplerKind::kIndependent);
    double landed = 0;
    light_tracer.walk(sampler, [&](const LightTracer::Landing& l) {
      if (std::hypot(l.point.x, l.point.z) <= kReach && std::abs(l.point.y) < 1e-3f)
        landed += l.flux.g;
    });
    sum += landed;
    sum2 += landed * landed;
  }
  const double mean = sum / kParticles;
  const double standard_error =
      std::sqrt(std::max(0.0, sum2 / kParticles - mean * mean) / (kParticles - 1));
  const double expected = analyticCausticPower(kRadius, kHeight, kIor, 1.0, kReach);
  // Allowance: the 128 × 256 tessellation (its facets lie within 3·10⁻⁴ R of the sphere).
  EXPECT_TRUE(kFamily.zTest(mean, expected, standard_error, 2e-3 * expected))
      << "analytic " << expected;
  EXPECT_GT(expected, 0.5 * M_PI);  // most of the light the sphere intercepts lands
}

// With an area light both the light and the camera paths reach the caustics: the class
// L S+ D E rendered each way estimates the same image.
TEST(Caustic, LightPathsAndCameraPathsAgreeOnTheSpheresBox) {
  const scene::Scene box = scene::loadScene("cornell", {"spheres=glass"});
  RenderSettings settings;
  settings.width = settings.height = 16;
  settings.spp = 64;
  settings.path_class.expression = "LS+DE";
  const RenderResult light = renderReference(box, settings);
  settings.light_paths = LightPaths::kOff;
  settings.seed = 1;
  settings.spp = 256;
  const RenderResult camera = renderReference(box, settings);
  ASSERT_TRUE(light.light_paths);
  const test::MeanEstimate d = test::difference(imageMean(light), imageMean(camera));
  EXPECT_GT(imageMean(light).mean, 0.0);
  EXPECT_TRUE(kFamily.tTest(d.mean, 0.0, d.standard_error, d.dof));
}

// Disjoint classes covering every path add up to the full render: L D* E (no specular vertex)
// and L (D|S)* S (D|S)* E (at least one), on the spheres box and on the chamber.
TEST(PathClasses, DisjointClassesAddUpToTheFullRender) {
  for (const auto& [name, set] :
       {std::pair<const char*, const char*>{"cornell", "spheres=mirror_glass"},
        {"chamber", nullptr}}) {
    const scene::Scene scene =
        set ? scene::loadScene(name, {set}) : scene::loadScene(name, std::vector<std::string>{});
    RenderSettings settings;
    settings.width = settings.height = 16;
    settings.spp = 64;
    const RenderResult full = renderReference(scene, settings);
    settings.seed = 1;
    settings.path_class.expression = "LD*E";
    const RenderResult diffuse = renderReference(scene, settings);
    settings.seed = 2;
    settings.path_class.expression = "L(D|S)*S(D|S)*E";
    const RenderResult specular = renderReference(scene, settings);
    const test::MeanEstimate parts = {
        imageMean(diffuse).mean + imageMean(specular).mean,
        std::hypot(imageMean(diffuse).standard_error, imageMean(specular).standard_error),
        std::min(imageMean(diffuse).dof, imageMean(specular).dof)};
    const test::MeanEstimate d = test::difference(imageMean(full), parts);
    EXPECT_TRUE(kFamily.tTest(d.mean, 0.0, d.standard_error, d.dof)) << name;
  }
}

// With one seed the classes split every sample's paths: each value of the full render is the sum
// of the two classes' values up to float rounding (a check that no path is counted twice or
// dropped, far sharper than the statistical test).
TEST(PathClasses, ClassesSplitEverySampleExactly) {
  const scene::Scene box = scene::loadScene("cornell", {"spheres=mirror_glass"});
  RenderSettings settings;
  settings.width = settings.height = 8;
  settings.spp = 16;
  const RenderResult full = renderReference(box, settings);
  settings.path_class.expression = "LD*E";
  const RenderResult diffuse = renderReference(box, settings);
  settings.path_class.expression = "L(D|S)*S(D|S)*E";
  const RenderResult specular = renderReference(box, settings);
  for (std::size_t i = 0; i < full.mean.data().size(); ++i)
    EXPECT_NEAR(full.mean.data()[i], diffuse.mean.data()[i] + specular.mean.data()[i],
                1e-4f * (1.0f + full.mean.data()[i]))
        << "value " << i;
}

// The light paths' splats land in whatever pixel they project to, from any thread: they are kept
// per tile and added in tile order, so the image is the same bit for bit on one thread or many.
TEST(LightPaths, ImageIsBitIdenticalAcrossThreadCounts) {
  const scene::Scene box = scene::loadScene("cornell", {"spheres=glass", "light=spot"});
  RenderSettings settings;
  settings.width = settings.height = 24;
  settings.spp = 8;
  settings.threads = 1;
  const RenderResult one = renderReference(box, settings);
  settings.threads = 2;
  const RenderResult two = renderReference(box, settings);
  ASSERT_TRUE(one.light_paths);
  EXPECT_TRUE(std::ranges::equal(one.mean.data(), two.mean.data()));
  EXPECT_TRUE(std::ranges::equal(one.variance.data(), two.variance.data()));
}

}  // namespace
}  // namespace gib::ref
