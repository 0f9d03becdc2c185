// The light samples of `direct`: every light type turned into point and directional samples that
// carry the light's whole power, deterministically.
#include "realtime/lighting/light_samples.h"

#include "scene/builtin_scenes.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace gib::rt {
namespace {

TEST(Hammersley, FirstCoordinateIsStratifiedSecondIsTheRadicalInverse) {
  EXPECT_FLOAT_EQ(hammersley(0, 4).x, 0.125f);
  EXPECT_FLOAT_EQ(hammersley(3, 4).x, 0.875f);
  EXPECT_FLOAT_EQ(hammersley(0, 8).y, 0.0f);
  EXPECT_FLOAT_EQ(hammersley(1, 8).y, 0.5f);
  EXPECT_FLOAT_EQ(hammersley(2, 8).y, 0.25f);
  EXPECT_FLOAT_EQ(hammersley(3, 8).y, 0.75f);
  EXPECT_FLOAT_EQ(hammersley(5, 8).y, 0.625f);
}

TEST(LightSamples, CornellLightSamplesCarryItsWholePowerAndLieOnIt) {
  const scene::Scene scene = scene::loadScene("cornell", {});
  const std::vector<EmitterTriangle> emitters = emitterTriangles(scene);
  ASSERT_EQ(emitters.size(), 2u);
  for (int count : {1, 2, 16, 64}) {
    const float lift = 0.5f;
    std::vector<LightSample> samples = makeLightSamples(scene, emitters, count, count, lift);
    ASSERT_EQ(samples.size(), std::size_t(count)) << "the Cornell box has no sky or spot";
    // Σ on-axis intensity = Σ radiance × area: the samples together emit the light's power.
    scene::Rgb total(0.0f);
    for (const LightSample& s : samples) {
      EXPECT_EQ(s.kind, LightSampleKind::kPoint);
      EXPECT_FLOAT_EQ(s.cos_cone, 0.0f);
      EXPECT_FLOAT_EQ(s.exponent, 1.0f);
      EXPECT_NEAR(s.axis.y, -1.0f, 1e-6f);
      // On the 130 × 105 mm light, lifted below it by `lift`, inside its rectangle.
      EXPECT_NEAR(s.position.y, emitters[0].a.y - lift, 1e-3f);
      EXPECT_GE(s.position.x, 213.0f);
      EXPECT_LE(s.position.x, 343.0f);
      EXPECT_GE(s.position.z, 227.0f);
      EXPECT_LE(s.position.z, 332.0f);
      total += s.intensity;
    }
    const scene::Rgb expected = emitters[0].emission * (emitters[0].area + emitters[1].area);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(total[c] / expected[c], 1.0f, 1e-5f) << count;
  }
}

TEST(LightSamples, SkyDirectionsCoverTheSphereWithItsIrradiance) {
  scene::Scene scene;
  scene.sky_radiance = scene::Rgb(2.0f);
  const int count = 256;
  std::vector<LightSample> samples = makeLightSamples(scene, {}, count, count, 0.0f);
  ASSERT_EQ(samples.size(), std::size_t(count));
  // Irradiance on an upward plane: Σ over directions from above of E_i cosθ → π L.
  double upward = 0, mean_axis_y = 0;
  for (const LightSample& s : samples) {
    EXPECT_EQ(s.kind, LightSampleKind::kDirectional);
    EXPECT_NEAR(glm::length(s.axis), 1.0f, 1e-5f);
    mean_axis_y += s.axis.y / count;
    if (s.axis.y < 0) upward += double(s.intensity.r) * double(-s.axis.y);
  }
  EXPECT_NEAR(upward / (std::numbers::pi * 2.0), 1.0, 0.01);
  EXPECT_NEAR(mean_axis_y, 0.0, 0.01);
}

TEST(LightSamples, SpotAndDirectionalLightsPassThroughUnchanged) {
  scene::Scene scene;
  scene::SpotLight spot;
  spot.position = {1, 2, 3};
  spot.direction = {0, -2, 0};
  spot.intensity = {5, 6, 7};
  spot.cone_angle_deg = 60;
  spot.falloff_exponent = 3;
  scene.spot_lights.push_back(spot);
  scene::DirectionalLight sun;
  sun.direction = {0, 0, -1};
  sun.irradiance = {1, 1, 1};
  scene.directional_lights.push_back(sun);
  std::vector<LightSample> samples = makeLightSamples(scene, {}, 16, 16, 0.0f);
  ASSERT_EQ(samples.size(), 2u);
  EXPECT_EQ(samples[0].kind, LightSampleKind::kPoint);
  EXPECT_FLOAT_EQ(samples[0].axis.y, -1.0f);
  EXPECT_NEAR(samples[0].cos_cone, 0.5f, 1e-6f);
  EXPECT_FLOAT_EQ(samples[0].exponent, 3.0f);
  EXPECT_EQ(samples[0].intensity, spot.intensity);
  EXPECT_EQ(samples[1].kind, LightSampleKind::kDirectional);
  EXPECT_EQ(samples[1].intensity, sun.irradiance);
}

// What a point sample delivers (pointSampleIrradiance, shared by the shading passes and the CPU
// irradiance cache): I·cos^n θ / d² inside its cone, for the exponents with shortcuts (0, 1) and
// without (2.5); zero outside the cone; and never negative behind a cone wider than a hemisphere,
// where cos θ < 0.
TEST(LightSamples, PointSampleIrradianceFollowsItsFalloffAndIsNeverNegative) {
  for (const float exponent : {0.0f, 1.0f, 2.5f}) {
    LightSample s;
    s.position = {0.0f, 2.0f, 0.0f};
    s.axis = {0.0f, -1.0f, 0.0f};
    s.intensity = scene::Rgb(3.0f);
    s.exponent = exponent;
    s.cos_cone = -1.0f;  // every direction
    const gpu::GpuLightSample g = toGpuLightSample(s);
    const glm::vec3 p(1.0f, 0.0f, 0.5f);  // below the light, off axis
    const glm::vec3 to_p = p - s.position;
    const float d2 = glm::dot(to_p, to_p), cos_theta = -to_p.y / std::sqrt(d2);
    const glm::vec4 lit = gpu::pointSampleIrradiance(g, p);
    EXPECT_EQ(lit.w, 1.0f);
    EXPECT_NEAR(lit.x, 3.0f * std::pow(cos_theta, exponent) / d2, 1e-6f) << exponent;
    const glm::vec4 behind = gpu::pointSampleIrradiance(g, glm::vec3(1.0f, 3.0f, 0.0f));
    EXPECT_GE(behind.x, 0.0f) << exponent;
    if (exponent > 0.0f) {
      EXPECT_EQ(behind.x, 0.0f) << exponent;
    }
    s.cos_cone = 0.9f;  // a narrow spot: p lies outside it
    EXPECT_EQ(gpu::pointSampleIrradiance(toGpuLightSample(s), p), glm::vec4(0.0f)) << exponent;
  }
}

}  // namespace
}  // namespace gib::rt
