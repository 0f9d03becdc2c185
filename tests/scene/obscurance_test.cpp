// The obscurance's definition and the ambient light of book Ch. 10 (scene/obscurance.h): names,
// the fall-off, and the scene's averages on a scene whose sums are worked out by hand.
#include "scene/obscurance.h"

#include "common/input_error.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace gib::scene {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
// Sums of a handful of areas in double, converted to float once: a few float ulps.
constexpr float kTolerance = 1e-6f;

void expectRgbNear(const Rgb& actual, const Rgb& expected, float tolerance = kTolerance) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], expected[c], tolerance) << "channel " << c;
}

TEST(Obscurance, NamesParseBackAndOthersAreInputErrors) {
  for (ObscuranceFalloff f : {ObscuranceFalloff::kSqrt, ObscuranceFalloff::kAmbientOcclusion})
    EXPECT_EQ(parseObscuranceFalloff(obscuranceFalloffName(f)), f);
  for (ObscuranceMode m : {ObscuranceMode::kScalar, ObscuranceMode::kSpectral})
    EXPECT_EQ(parseObscuranceMode(obscuranceModeName(m)), m);
  EXPECT_THROW(parseObscuranceFalloff("step"), InputError);
  EXPECT_THROW(parseObscuranceMode("colour"), InputError);
  EXPECT_EQ(describeObscurance({}), "obscurance(sqrt, scalar, d_max=0.25)");
  EXPECT_EQ(
      describeObscurance({ObscuranceFalloff::kAmbientOcclusion, ObscuranceMode::kSpectral, 0.1f}),
      "obscurance(ambient_occlusion, spectral, d_max=0.1)");
}

TEST(Obscurance, DistanceFractionMustBePositiveAndFinite) {
  EXPECT_NO_THROW(validateObscuranceDistanceFraction(0.25f));
  EXPECT_NO_THROW(validateObscuranceDistanceFraction(2.0f));
  for (float bad : {0.0f, -0.5f, std::numeric_limits<float>::quiet_NaN(),
                    std::numeric_limits<float>::infinity(), 1e6f})
    EXPECT_THROW(validateObscuranceDistanceFraction(bad), InputError) << bad;
}

TEST(Obscurance, FalloffIsTheBooksSquareRootOrAStep) {
  EXPECT_FLOAT_EQ(obscuranceFalloff(kObscuranceFalloffSqrt, 0.25f, 1.0f), 0.5f);
  EXPECT_FLOAT_EQ(obscuranceFalloff(kObscuranceFalloffSqrt, 0.0f, 1.0f), 0.0f);
  EXPECT_FLOAT_EQ(obscuranceFalloff(kObscuranceFalloffStep, 0.99f, 1.0f), 0.0f);
  for (int f : {kObscuranceFalloffSqrt, kObscuranceFalloffStep}) {
    EXPECT_FLOAT_EQ(obscuranceFalloff(f, 1.0f, 1.0f), 1.0f);
    EXPECT_FLOAT_EQ(obscuranceFalloff(f, std::numeric_limits<float>::infinity(), 1.0f), 1.0f);
  }
  // Spectral: ρ·a for a hit nearer than d_max, the average albedo beyond it and for a miss.
  const Rgb a(0.8f, 0.4f, 0.2f), average(0.5f, 0.6f, 0.7f);
  expectRgbNear(obscuranceSample(true, kObscuranceFalloffSqrt, 0.25f, 1.0f, a, average), 0.5f * a);
  expectRgbNear(obscuranceSample(true, kObscuranceFalloffSqrt, 2.0f, 1.0f, a, average), average);
  expectRgbNear(obscuranceSample(false, kObscuranceFalloffSqrt, 0.25f, 1.0f, a, average),
                Rgb(0.5f));
}

TEST(Obscurance, SpotLightsPowerIsTheConesIntegral) {
  SpotLight spot;
  spot.cone_angle_deg = 90.0f;
  spot.falloff_exponent = 1.0f;
  EXPECT_NEAR(spotSolidAngleIntegral(spot), kPi, 1e-6f);  // ∫ cos θ over the hemisphere
  spot.cone_angle_deg = 60.0f;
  spot.falloff_exponent = 0.0f;
  EXPECT_NEAR(spotSolidAngleIntegral(spot), kPi, 1e-6f);  // the cap's solid angle 2π(1 − ½)
  // A cone wider than a hemisphere with k > 0 stops at the hemisphere.
  spot.cone_angle_deg = 120.0f;
  spot.falloff_exponent = 2.0f;
  EXPECT_FLOAT_EQ(spotEdgeCosine(spot), 0.0f);
  EXPECT_NEAR(spotSolidAngleIntegral(spot), 2.0f * kPi / 3.0f, 1e-6f);
}

// A 2 × 2 floor of albedo (0.5, 0.5, 0.25), a 1 × 1 emitter of radiance 10 and albedo 0, and a
// hemispherical spot of intensity 5 W/sr falling off as cos θ (power 5π, so A·Lᵉ = 5).
Scene makeHandComputedScene() {
  Scene s;
  Material floor;
  floor.name = "floor";
  floor.diffuse = Rgb(0.5f, 0.5f, 0.25f);
  Material light;
  light.name = "light";
  light.emission = Rgb(10.0f);
  s.materials = {floor, light};
  Mesh floor_mesh;
  floor_mesh.material = 0;
  appendQuad(floor_mesh, {-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1});
  Mesh light_mesh;
  light_mesh.material = 1;
  appendQuad(light_mesh, {0, 2, 0}, {1, 2, 0}, {1, 2, 1}, {0, 2, 1});
  s.meshes = {floor_mesh, light_mesh};
  SpotLight spot;
  spot.intensity = Rgb(5.0f);
  spot.cone_angle_deg = 90.0f;
  spot.falloff_exponent = 1.0f;
  s.spot_lights = {spot};
  return s;
}

TEST(Obscurance, SceneAveragesAndAmbientLightOfAHandComputedScene) {
  const Scene s = makeHandComputedScene();
  const SceneAverages averages = sceneAverages(s);
  // S = 4 + 1; ã = (4·(0.5, 0.5, 0.25) + 1·0)/5; L̃ᵉ = (1·10 + 5)/5.
  EXPECT_NEAR(averages.area, 5.0, 1e-12);
  expectRgbNear(averages.albedo, Rgb(0.4f, 0.4f, 0.2f));
  expectRgbNear(averages.emitted_per_area, Rgb(3.0f));
  // Eq. 10.3: ã/(1 − ã)·L̃ᵉ; eq. 10.5: L̃ᵉ/(1 − ā).
  expectRgbNear(ambientLight(averages, ObscuranceMode::kScalar), Rgb(2.0f, 2.0f, 0.75f), 1e-5f);
  expectRgbNear(ambientLight(averages, ObscuranceMode::kSpectral), Rgb(5.0f, 5.0f, 3.75f), 1e-5f);
  // The bounding box is 2 × 2 × 2.
  EXPECT_NEAR(sceneDiagonal(s), 2.0f * std::sqrt(3.0f), 1e-6f);
  EXPECT_NEAR(maxDistance(s, {ObscuranceFalloff::kSqrt, ObscuranceMode::kScalar, 0.5f}),
              std::sqrt(3.0f), 1e-6f);
}

TEST(Obscurance, AnAlbedoOfOneIsClampedSoTheSeriesConverges) {
  SceneAverages averages;
  averages.area = 1;
  averages.albedo = Rgb(1.0f);
  averages.emitted_per_area = Rgb(1.0f);
  const Rgb ambient = ambientLight(averages, ObscuranceMode::kSpectral);
  EXPECT_TRUE(std::isfinite(ambient.r));
  EXPECT_NEAR(ambient.r, 1000.0f, 0.1f);  // 1/(1 − 0.999) with 0.999 in float
}

TEST(Obscurance, MirrorsAndGlassHaveNoAlbedo) {
  Material m;
  m.diffuse = Rgb(0.3f);
  EXPECT_EQ(obscuranceAlbedo(m), Rgb(0.3f));
  m.type = MaterialType::kPhong;
  EXPECT_EQ(obscuranceAlbedo(m), Rgb(0.3f));
  m.type = MaterialType::kMirror;
  EXPECT_EQ(obscuranceAlbedo(m), Rgb(0.0f));
  m.type = MaterialType::kGlass;
  EXPECT_EQ(obscuranceAlbedo(m), Rgb(0.0f));
}

TEST(Obscurance, CornellBoxValuesAreSensible) {
  const Scene cornell = loadScene("cornell");
  const SceneAverages averages = sceneAverages(cornell);
  const Rgb scalar = ambientLight(averages, ObscuranceMode::kScalar);
  const Rgb spectral = ambientLight(averages, ObscuranceMode::kSpectral);
  fmt::print(
      "cornell: S = {:.4g} mm², ã = ({:.4f}, {:.4f}, {:.4f}), L̃ᵉ = ({:.4g}, {:.4g}, {:.4g}), "
      "Lᵃ scalar = ({:.4g}, {:.4g}, {:.4g}), spectral = ({:.4g}, {:.4g}, {:.4g}), diagonal {:.1f} "
      "mm\n",
      averages.area, averages.albedo.r, averages.albedo.g, averages.albedo.b,
      averages.emitted_per_area.r, averages.emitted_per_area.g, averages.emitted_per_area.b,
      scalar.r, scalar.g, scalar.b, spectral.r, spectral.g, spectral.b, sceneDiagonal(cornell));
  // The box is about 556 mm a side: walls, floor and ceiling of 0.3 m² each, and the two blocks.
  EXPECT_GT(averages.area, 5 * 0.3e6);
  EXPECT_LT(averages.area, 8 * 0.3e6);
  EXPECT_GT(sceneDiagonal(cornell), 900.0f);
  EXPECT_LT(sceneDiagonal(cornell), 1000.0f);
  for (int c = 0; c < 3; ++c) {
    // White walls of albedo about 0.75, a red and a green wall: an average well inside (0, 1).
    EXPECT_GT(averages.albedo[c], 0.3f);
    EXPECT_LT(averages.albedo[c], 0.8f);
    // The small light's emission spread over every surface: a few percent of its radiance.
    EXPECT_GT(averages.emitted_per_area[c], 0.0f);
    // Eq. 10.5's series starts one reflection earlier than 10.3's: it is larger by 1/ã.
    EXPECT_NEAR(spectral[c] * averages.albedo[c], scalar[c], 1e-5f * spectral[c]);
  }
}

}  // namespace
}  // namespace gib::scene
