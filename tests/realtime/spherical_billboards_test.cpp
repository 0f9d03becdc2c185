// The particle medium's shared pieces and spherical billboards (book §9.3–9.4): the linear
// fall-off's closed form against numerical integration, the phase table against the reference's
// Henyey–Greenstein, one particle's billboard transmittance against a ray march (and against a
// surface through it: spherical billboards clip, planar ones do not), volume shadowing against a
// ray march through the reference layer's density grid, one lit particle's scattered light
// against the same discretisation on the CPU, and the technique against the reference restricted
// to single scattering.
#include "realtime/techniques/spherical_billboards/spherical_billboards_technique.h"

#include "realtime/gl/pass_profiler.h"
#include "realtime/particles/particle_medium.h"
#include "realtime/particles/particle_shared.h"
#include "realtime/particles/volume_shadow.h"
#include "reference/phase_function.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"
#include "scene/medium.h"
#include "scene/mesh_builder.h"
#include "support/gl_test_context.h"
#include "support/medium_march.h"
#include "support/particle_lighting.h"
#include "support/technique_frame.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gib::rt {
namespace {

using test::marchedOpticalDepth;

TEST(ParticleOpticalDepth, ClosedFormEqualsNumericalIntegrationOfTheLinearFallOff) {
  const float tau = 1.7f, r = 1.3f;
  for (float d : {0.0f, 0.2f, 0.65f, 1.1f, 1.29f})
    for (auto [s0, s1] : {std::pair{-5.0f, 5.0f}, {-0.4f, 0.3f}, {0.1f, 2.0f}, {-2.0f, -0.5f}}) {
      const int steps = 200000;
      const double h = double(s1 - s0) / steps;
      double numeric = 0;
      for (int i = 0; i < steps; ++i) {
        const double s = s0 + (i + 0.5) * h;
        numeric += h * tau * std::max(0.0, 1.0 - std::sqrt(double(d) * d + s * s) / r);
      }
      EXPECT_NEAR(gpu::chordOpticalDepth(tau, r, d, s0, s1), numeric, 2e-5 * (1 + numeric))
          << "d " << d << " [" << s0 << ", " << s1 << "]";
    }
  // The whole chord through the centre is τ·r; nothing outside the sphere.
  EXPECT_NEAR(gpu::chordOpticalDepth(tau, r, 0.0f, -10.0f, 10.0f), tau * r, 1e-6);
  EXPECT_EQ(gpu::chordOpticalDepth(tau, r, 1.31f, -10.0f, 10.0f), 0.0f);
}

TEST(ParticlePhaseTable, HoldsTheReferencesHenyeyGreensteinAndIntegratesToOne) {
  for (float g : {0.0f, 0.5f, -0.3f, 0.8f}) {
    const std::vector<float> table = henyeyGreensteinTable(g);
    ASSERT_EQ(table.size(), std::size_t(gpu::kPhaseTableSize));
    double integral = 0;  // 2π ∫ p dμ by the trapezoidal rule over the table's cosines
    const double step = 2.0 / (gpu::kPhaseTableSize - 1);
    for (int i = 0; i < gpu::kPhaseTableSize; ++i) {
      const float mu = -1.0f + 2.0f * float(i) / float(gpu::kPhaseTableSize - 1);
      EXPECT_NEAR(table[std::size_t(i)], ref::henyeyGreenstein(mu, g),
                  1e-6f * ref::henyeyGreenstein(mu, g))
          << "g " << g << " cos " << mu;
      const double weight = (i == 0 || i == gpu::kPhaseTableSize - 1) ? 0.5 : 1.0;
      integral += 2.0 * M_PI * weight * step * table[std::size_t(i)];
    }
    EXPECT_NEAR(integral, 1.0, 2e-3) << "g " << g;
  }
}

// One particle (τ = 1.5, r = 1) at the origin seen from z = 5 against a unit sky, albedo 0: every
// pixel is the particle's transmittance along its ray. `wall` adds an emitter of radiance 1 at
// z = 0.3 over x ≥ 0, facing the camera, in front of the particle's centre.
scene::Scene oneParticle(bool wall) {
  scene::Scene s;
  s.name = "one-particle";
  s.camera.position = {0.0f, 0.0f, 5.0f};
  s.camera.look_at = {0.0f, 0.0f, 0.0f};
  s.camera.vertical_fov_deg = 30.0f;
  s.medium.particles = {{glm::vec3(0.0f), 1.0f, 1.5f}};
  s.medium.albedo = scene::Rgb(0.0f);
  s.sky_radiance = scene::Rgb(1.0f);
  if (wall) {
    scene::Material emitter;
    emitter.name = "wall";
    emitter.emission = scene::Rgb(1.0f);
    s.materials.push_back(emitter);
    scene::Mesh mesh;
    mesh.name = "wall";
    scene::appendQuad(mesh, {0, -3, 0.3f}, {3, -3, 0.3f}, {3, 3, 0.3f}, {0, 3, 0.3f});
    s.meshes.push_back(mesh);
  }
  return s;
}

struct ParticleRay {
  glm::vec3 origin, direction;
  std::optional<double> wall;  // ray distance to the wall, if the ray meets it
};

ParticleRay pixelRay(const scene::Scene& s, int size, int x, int y, bool wall) {
  const scene::CameraFrame frame = scene::makeCameraFrame(s.camera, size, size);
  ParticleRay ray{
      s.camera.position, scene::cameraRayDirection(frame, size, size, x + 0.5f, y + 0.5f), {}};
  if (wall) {
    const double t = (0.3 - ray.origin.z) / ray.direction.z;
    const glm::vec3 hit = ray.origin + float(t) * ray.direction;
    if (hit.x >= 0) ray.wall = t;
  }
  return ray;
}

class SphericalBillboards : public test::GlTest {};

// A fragment's opacity is the closed-form optical depth of its ray segment: within 1e-3 of the
// ray-marched transmittance at every pixel (every impact parameter from the centre to the rim).
// The book's approximations are measured against it and recorded; Gouraud's 1 − exp(−τ(1 − d/r)Δs)
// takes twice the optical depth through the centre, so it differs by more than 0.05 somewhere.
TEST_F(SphericalBillboards, OneParticlesTransmittanceIsTheLinearFallOffsClosedForm) {
  const scene::Scene s = oneParticle(false);
  const scene::DensityGrid medium(s.medium.particles);
  constexpr int kSize = 48;
  std::map<std::string, double> worst;
  for (const std::string opacity : {"linear", "gouraud", "homogeneous"}) {
    const image::Image image =
        test::renderOneFrame(s, "spherical_billboards", {"opacity=" + opacity}, kSize).image;
    int crossed = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const ParticleRay ray = pixelRay(s, kSize, x, y, false);
        const double expected =
            std::exp(-marchedOpticalDepth(medium, ray.origin, ray.direction, 3.5, 6.5, 4000));
        const double error = std::abs(image.pixel(x, y)[0] - expected);
        worst[opacity] = std::max(worst[opacity], error);
        if (opacity == "linear") {
          EXPECT_NEAR(image.pixel(x, y)[0], expected, 1e-3) << x << "," << y;
        }
        if (expected < 0.999) ++crossed;
      }
    EXPECT_GT(crossed, kSize * kSize / 8) << "the particle covers too few pixels to test";
    RecordProperty("max_transmittance_error_" + opacity, std::to_string(worst[opacity]));
  }
  EXPECT_GT(worst["gouraud"], 0.05);
  EXPECT_GT(worst["homogeneous"], 0.05);
}

// Where a surface cuts the particle, a spherical billboard integrates only the segment in front of
// it (within 1e-3 of the march), and a planar one, depth-tested at its centre behind the wall,
// vanishes there (transmittance 1: the clipping artefact of Fig. 9.3). Off the wall both show the
// whole segment.
TEST_F(SphericalBillboards, SphericalBillboardsClipAgainstSurfacesAndPlanarOnesVanishBehindThem) {
  const scene::Scene s = oneParticle(true);
  const scene::DensityGrid medium(s.medium.particles);
  constexpr int kSize = 48;
  const TechniqueRunResult run =
      test::renderOneFrame(s, "spherical_billboards", {"billboard=spherical"}, kSize);
  const image::Image& spherical = run.image;
  ASSERT_EQ(run.auxiliary.size(), 1u);
  const image::Image& clipping = run.auxiliary[0].image;  // |planar − spherical| / its largest
  const image::Image planar =
      test::renderOneFrame(s, "spherical_billboards", {"billboard=planar"}, kSize).image;
  // The clipping image's scale: the largest difference, which it maps to 1.
  float clipping_scale = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      clipping_scale =
          std::max(clipping_scale, std::abs(planar.pixel(x, y)[0] - spherical.pixel(x, y)[0]));
  int clipped = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const ParticleRay ray = pixelRay(s, kSize, x, y, true);
      const glm::vec3 edge =
          ray.origin + float((0.3 - ray.origin.z) / ray.direction.z) * ray.direction;
      if (std::abs(edge.x) < 0.05f) continue;  // the wall's edge: either side may rasterize
      const double whole =
          std::exp(-marchedOpticalDepth(medium, ray.origin, ray.direction, 3.5, 6.5, 4000));
      if (!ray.wall) {
        EXPECT_NEAR(spherical.pixel(x, y)[0], whole, 1e-3) << x << "," << y;
        EXPECT_NEAR(planar.pixel(x, y)[0], whole, 1e-3) << x << "," << y;
        EXPECT_EQ(clipping.pixel(x, y)[0], 0.0f) << x << "," << y;
        continue;
      }
      EXPECT_NEAR(clipping.pixel(x, y)[0] * clipping_scale,
                  std::abs(planar.pixel(x, y)[0] - spherical.pixel(x, y)[0]), 1e-4);
      const double front =
          std::exp(-marchedOpticalDepth(medium, ray.origin, ray.direction, 3.5, *ray.wall, 4000));
      EXPECT_NEAR(spherical.pixel(x, y)[0], front, 1e-3) << x << "," << y;
      EXPECT_NEAR(planar.pixel(x, y)[0], 1.0, 1e-5) << x << "," << y;
      if (front < 0.95) ++clipped;
    }
  EXPECT_GT(clipped, 40);
}

// A camera inside a particle (the book's popping, Fig. 9.4): a spherical billboard integrates the
// segment from the near plane to the sphere's exit (within 1e-3 of the march), wherever the eye is
// in the sphere. A planar billboard takes the whole chord while the centre is ahead, behind the
// eye too (darker than the truth), and vanishes once the centre is behind the eye: transmittance 1.
TEST_F(SphericalBillboards, SphericalBillboardsDoNotPopWhenTheCameraIsInsideAParticle) {
  constexpr int kSize = 24;
  for (float eye_z : {0.5f, -0.5f}) {
    scene::Scene s = oneParticle(false);
    s.camera.position = {0.0f, 0.0f, eye_z};
    s.camera.look_at = {0.0f, 0.0f, eye_z - 1.0f};
    const scene::DensityGrid medium(s.medium.particles);
    const image::Image spherical =
        test::renderOneFrame(s, "spherical_billboards", {"billboard=spherical"}, kSize).image;
    const image::Image planar =
        test::renderOneFrame(s, "spherical_billboards", {"billboard=planar"}, kSize).image;
    for (int y = 0; y < kSize; y += 3)
      for (int x = 0; x < kSize; x += 3) {
        const ParticleRay ray = pixelRay(s, kSize, x, y, false);
        const double ahead =
            std::exp(-marchedOpticalDepth(medium, ray.origin, ray.direction, 0.0, 2.0, 4000));
        EXPECT_NEAR(spherical.pixel(x, y)[0], ahead, 1e-3) << eye_z << " " << x << "," << y;
        if (eye_z < 0) {
          EXPECT_EQ(planar.pixel(x, y)[0], 1.0f) << x << "," << y;
        } else {
          EXPECT_LT(planar.pixel(x, y)[0], ahead - 0.02) << x << "," << y;
        }
      }
  }
}

// Surfaces are lit through the medium: a particle between a directional light and a floor
// darkens the floor by its transmittance along the light's direction (within 1e-3 of a march),
// and surface_shadow=false leaves the floor lit as if the medium were not there.
TEST_F(SphericalBillboards, SurfacesAreLitThroughTheMediumsTransmittance) {
  scene::Scene s = test::floorScene();
  s.directional_lights = {{glm::normalize(glm::vec3(1, -1, 0)), scene::Rgb(1.0f)}};
  s.medium.particles = {{glm::vec3(-0.8f, 0.8f, 0.0f), 0.4f, 3.0f}};
  s.medium.albedo = scene::Rgb(0.0f);
  const scene::DensityGrid medium(s.medium.particles);
  constexpr int kSize = 48;
  const image::Image shadowed = test::renderOneFrame(s, "spherical_billboards", {}, kSize).image;
  const image::Image unshadowed =
      test::renderOneFrame(s, "spherical_billboards", {"surface_shadow=false"}, kSize).image;
  const scene::CameraFrame frame = scene::makeCameraFrame(s.camera, kSize, kSize);
  const float lit = 0.5f / float(M_PI) * std::sqrt(0.5f);  // ρ/π · E · cos 45°
  int darkened = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const glm::vec3 d = scene::cameraRayDirection(frame, kSize, kSize, x + 0.5f, y + 0.5f);
      const glm::vec3 floor = s.camera.position + (-s.camera.position.y / d.y) * d;
      if (std::abs(floor.x) > 1.9f || std::abs(floor.z) > 1.9f) continue;  // off or at the edge
      if (marchedOpticalDepth(medium, s.camera.position, d, 0.0, 4.0, 2000) > 0) continue;
      const double transmittance = std::exp(
          -marchedOpticalDepth(medium, floor, glm::normalize(glm::vec3(-1, 1, 0)), 0.0, 4.0, 4000));
      EXPECT_NEAR(shadowed.pixel(x, y)[0], lit * transmittance, 1e-3 * lit) << x << "," << y;
      EXPECT_NEAR(unshadowed.pixel(x, y)[0], lit, 1e-3 * lit) << x << "," << y;
      if (transmittance < 0.8) ++darkened;
    }
  EXPECT_GT(darkened, 20);
}

// Each particle's transmittance towards a direction through the rest of the cloud equals the
// optical depth marched through the density grid of the other particles, within 1e-3.
TEST_F(SphericalBillboards, VolumeShadowEqualsARayMarchThroughTheOtherParticles) {
  const scene::Scene s = scene::loadScene("cloud", {"particles=40", "seed=3"});
  const ParticleMedium medium(s, "test");
  std::vector<glm::vec4> directions = medium.towardsLights();
  directions.push_back(glm::vec4(glm::normalize(glm::vec3(0.2f, 1.0f, -0.4f)), 0.0f));
  directions.push_back(glm::vec4(0.0f, 0.0f, 1.0f, 0.0f));
  const gl::Buffer buffer = gl::Buffer::fromVector(directions);
  gl::Buffer transmittance;
  VolumeShadow().compute(medium, buffer, int(directions.size()), transmittance);
  const std::size_t n = s.medium.particles.size(), m = directions.size();
  const std::vector<float> gpu = gl::readBuffer<float>(transmittance, n * m);
  double lowest = 1;
  for (std::size_t p = 0; p < n; ++p) {
    std::vector<scene::MediumParticle> others = s.medium.particles;
    others.erase(others.begin() + std::ptrdiff_t(p));
    const scene::DensityGrid grid(others);
    for (std::size_t k = 0; k < m; ++k) {
      const double expected = std::exp(-marchedOpticalDepth(
          grid, s.medium.particles[p].centre, glm::vec3(directions[k]), 0.0, 30.0, 30000));
      EXPECT_NEAR(gpu[p * m + k], expected, 1e-3) << "particle " << p << " direction " << k;
      lowest = std::min(lowest, expected);
    }
  }
  EXPECT_LT(lowest, 0.5) << "no particle is shadowed: the test would not see a wrong sum";
}

// One particle (τ = 1.5, r = 1) under a directional light, albedo 0.8, g = 0.5, no sky: nothing
// else lights or shadows it, and the technique leaves its own density out (volume_shadow), so
// every pixel is the particle's opacity along its ray times its radiance per unit opacity
// a·p(ω_l·v)·E (view_shading.comp.glsl), with v the direction from its centre to the eye and p
// the reference's Henyey–Greenstein: the same discretisation evaluated on the CPU. The opacity
// is the march's to 1e-3 (above), so every pixel is within 1e-3·a·p·E of it; scattered light
// off by 2% (a light's irradiance, the phase table, the albedo) is off by ten times that wherever
// the opacity exceeds a half.
TEST_F(SphericalBillboards, OneLitParticleScattersItsOpacityTimesTheLightsPhaseWeightedIrradiance) {
  scene::Scene s = oneParticle(false);
  s.sky_radiance = scene::Rgb(0.0f);
  s.medium.albedo = scene::Rgb(0.8f);
  s.medium.g = 0.5f;
  const glm::vec3 propagation = glm::normalize(glm::vec3(0.5f, -0.4f, 0.77f));  // towards the eye
  s.directional_lights = {{propagation, scene::Rgb(2.0f)}};
  const scene::DensityGrid medium(s.medium.particles);
  constexpr int kSize = 32;
  const image::Image image = test::renderOneFrame(s, "spherical_billboards", {}, kSize).image;
  const glm::vec3 v = glm::normalize(s.camera.position - s.medium.particles[0].centre);
  const double per_opacity = 0.8 * ref::henyeyGreenstein(glm::dot(propagation, v), 0.5f) * 2.0;
  int opaque = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const ParticleRay ray = pixelRay(s, kSize, x, y, false);
      const double opacity =
          1 - std::exp(-marchedOpticalDepth(medium, ray.origin, ray.direction, 3.5, 6.5, 4000));
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(image.pixel(x, y)[c], opacity * per_opacity, 1e-3 * per_opacity)
            << x << "," << y;
      if (opacity > 0.5) ++opaque;
    }
  EXPECT_GT(opaque, kSize * kSize / 16) << "the particle covers too few pixels to test";
}

// The whole technique on a cloud of 256 particles at 32² against the reference restricted to
// single scattering (the class it models), 64 spp in 16 replicas (a variance layer with 15
// degrees of freedom). The densities are quartered (as for the lossless cloud of the network's
// tests), so that lighting each particle at its centre, the technique's approximation, costs
// little and its allowance (centreLightingAllowance: 4.4% of the scattered light here, 8.8% in
// a pixel) leaves the test its power: without the fill light the scattered light is 11% short,
// which the full cloud's 20% allowance would not see. The sky transmitted through the medium is
// rendered exactly (albedo 0); the scattered light's sum and the relMSE less the reference's
// noise are held to the allowance plus their standard errors' family-wise bound (1%, two
// estimates). A scattered light wrong by a small scale is OneLitParticle…'s to find.
TEST_F(SphericalBillboards, MatchesTheSingleScatteringReference) {
  scene::Scene s = scene::loadScene("cloud", {"particles=256"});
  for (scene::MediumParticle& p : s.medium.particles) p.density *= 0.25f;
  scene::Scene absorbing = s;
  absorbing.medium.albedo = scene::Rgb(0.0f);
  constexpr int kSize = 32;
  const image::Image image = test::renderOneFrame(s, "spherical_billboards", {}, kSize).image;
  const image::Image transmitted =
      test::renderOneFrame(absorbing, "spherical_billboards", {}, kSize).image;
  const ref::RenderResult reference = test::renderClassReference(s, kSize, 64, {0, 1}, 16);
  const test::CentreLightingAllowance allowance = test::centreLightingAllowance(s.medium.particles);
  const test::ScatteredLightMatch match =
      test::matchScatteredLight(reference, image, transmitted, allowance);
  RecordProperty("scattered_light_ratio", std::to_string(match.ratio.mean));
  RecordProperty("relmse_less_noise", std::to_string(match.relmse.mean));
  std::printf(
      "scattered light ratio %.4f ± %.4f (allowance %.4f); relMSE less noise %.6f ± %.6f "
      "(allowance %.6f)\n",
      match.ratio.mean, match.ratio.standard_error, allowance.mean, match.relmse.mean,
      match.relmse.standard_error, match.relmse_allowance);
  // The ratio and the relMSE: a family of two at 1%.
  test::expectScatteredLightMatches(match, allowance, test::TestFamily(0.01, 2));
}

}  // namespace
}  // namespace gib::rt
