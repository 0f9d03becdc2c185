// The environment map (scene/environment_map.h) and its importance distribution
// (scene/environment_distribution.h): the latitude–longitude convention, the rotation, the checks
// of bad maps, the map's integral, and the sampler against its own density (chi-square).
#include "scene/environment_map.h"
#include "common/input_error.h"
#include "image/exr_io.h"
#include "scene/environment_distribution.h"
#include "scene/scene.h"
#include "support/statistical_test.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <numbers>

namespace gib::scene {
namespace {

constexpr double kPi = std::numbers::pi;

// A correct sampler fails one of this file's three statistical tests (the chi-square tests of a
// smooth map and of a map with a bright spot, the binomial test of two texels' shares) with
// probability 1%.
constexpr test::TestFamily kFamily(0.01, 3);

// A map whose texel (x, y) is value(x, y) in every channel.
template <typename Value>
EnvironmentMap greyMap(int height, Value value) {
  const int width = 2 * height;
  std::vector<float> texels;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) texels.push_back(float(value(x, y)));
  return makeEnvironmentMap(width, height, std::move(texels), "test");
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(EnvironmentMap, LatitudeLongitudeConvention) {
  // Row 0 looks up, the middle of the map along the horizon; u starts at +x and grows towards +z.
  EXPECT_FLOAT_EQ(latLongCoordinates({0, 1, 0}).y, 0.0f);
  EXPECT_NEAR(latLongCoordinates({0, -1, 0}).y, 1.0f, 1e-6f);
  EXPECT_FLOAT_EQ(latLongCoordinates({1, 0, 0}).x, 0.0f);
  EXPECT_FLOAT_EQ(latLongCoordinates({0, 0, 1}).x, 0.25f);
  EXPECT_FLOAT_EQ(latLongCoordinates({-1, 0, 0}).x, 0.5f);
  EXPECT_FLOAT_EQ(latLongCoordinates({0, 0, -1}).x, 0.75f);
  EXPECT_FLOAT_EQ(latLongCoordinates({1, 0, 0}).y, 0.5f);
  // No direction: the first texel, not NaN (which would index anywhere).
  EXPECT_EQ(latLongCoordinates({0, 0, 0}), glm::vec2(0.0f));
  EXPECT_EQ(latLongCoordinates({std::numeric_limits<float>::quiet_NaN(), 1, 0}), glm::vec2(0.0f));
  // Round trips through every octant, and the length of the direction does not matter.
  for (const glm::vec3 d : {glm::vec3(0.3f, 0.8f, -0.5f), glm::vec3(-0.7f, -0.2f, 0.4f),
                            glm::vec3(-0.1f, 0.05f, -0.9f), glm::vec3(0.6f, -0.6f, 0.52f)}) {
    expectNear(latLongDirection(latLongCoordinates(d)), glm::normalize(d), 1e-6f);
    expectNear(latLongDirection(latLongCoordinates(3.0f * d)), glm::normalize(d), 1e-6f);
  }
}

TEST(EnvironmentMap, RotationTurnsTheMapFromXTowardsMinusZ) {
  EnvironmentMap map = greyMap(4, [](int x, int) { return x; });
  map.rotation_deg = 90.0f;
  expectNear(map.toWorld({1, 0, 0}), {0, 0, -1}, 1e-6f);
  expectNear(map.toMap(map.toWorld({0.2f, 0.5f, 0.7f})), {0.2f, 0.5f, 0.7f}, 1e-6f);
  // What the map holds at +x (column 0, value 0) the world sees at −z; what it holds at +z
  // (u = 1/4, column 2) the world sees at +x.
  EXPECT_EQ(map.radiance({0, 0.1f, -1}).r, 0.0f);
  EXPECT_EQ(map.radiance({1, 0.1f, 0.001f}).r, 2.0f);
  map.intensity = 3.0f;
  EXPECT_EQ(map.radiance({1, 0.1f, 0.001f}).r, 6.0f);
}

TEST(EnvironmentMap, IntegralOfAConstantMapIsFourPiTimesItsRadiance) {
  EnvironmentMap map = greyMap(16, [](int, int) { return 0.75; });
  map.intensity = 2.0f;
  EXPECT_NEAR(environmentIntegral(map).g, 4 * kPi * 0.75 * 2.0, 1e-4);
}

TEST(EnvironmentMap, RefusesMapsThatAreNotLatitudeLongitudeRadiance) {
  auto refused = [](int width, int height, std::vector<float> texels, const char* needle) {
    try {
      makeEnvironmentMap(width, height, std::move(texels), "test");
      ADD_FAILURE() << "accepted a bad map: " << needle;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  refused(6, 2, std::vector<float>(36, 1.0f), "not a latitude");
  refused(0, 0, {}, "not a latitude");
  refused(4, 2, std::vector<float>(23, 1.0f), "values for");
  std::vector<float> nan(24, 1.0f);
  nan[7] = std::numeric_limits<float>::quiet_NaN();
  refused(4, 2, nan, "texel (2, 0)");
  std::vector<float> negative(24, 1.0f);
  negative[23] = -0.5f;
  refused(4, 2, negative, "texel (3, 1) has B value -0.5");
  EnvironmentMap map = greyMap(2, [](int, int) { return 1; });
  map.intensity = -1.0f;
  EXPECT_THROW(validateEnvironmentMap(map), InputError);
}

TEST(EnvironmentMap, ReadsAnExrAndRefusesOneThatIsNotTwoToOne) {
  test::TempDir dir;
  image::Image rgb(8, 4);
  rgb.pixel(5, 1)[1] = 2.5f;
  image::writeExr(dir.path() / "map.exr", {{"", rgb}}, {});
  const EnvironmentMap map = loadEnvironmentMap(dir.path() / "map.exr");
  EXPECT_EQ(map.width, 8);
  EXPECT_EQ(map.texel(5, 1), Rgb(0.0f, 2.5f, 0.0f));
  image::writeExr(dir.path() / "square.exr", {{"", image::Image(4, 4)}}, {});
  try {
    loadEnvironmentMap(dir.path() / "square.exr");
    ADD_FAILURE() << "accepted a square map";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("square.exr"), std::string::npos) << e.what();
  }
}

TEST(EnvironmentMap, SceneHashChangesWithTheMapAndOnlyWithIt) {
  Scene scene;
  scene.camera.look_at = {0, 0, -1};
  const std::string without = hashScene(scene);
  scene.environment = greyMap(4, [](int x, int y) { return x + y; });
  const std::string with = hashScene(scene);
  EXPECT_NE(with, without);
  scene.environment.rotation_deg = 10.0f;
  EXPECT_NE(hashScene(scene), with);
  scene.environment.source = "elsewhere";  // provenance: not hashed
  scene.environment.rotation_deg = 0.0f;
  EXPECT_EQ(hashScene(scene), with);
  scene.sky_radiance = Rgb(1.0f);
  EXPECT_THROW(validateScene(scene), InputError) << "a sky and a map at once";
}

// The sampler's own density and the one pdf() gives agree, and the draws follow it.
void expectSamplerMatchesDensity(const EnvironmentMap& map) {
  const EnvironmentDistribution distribution(map);
  ref::SampleStream stream(7, 0, 0);
  for (int i = 0; i < 1000; ++i) {
    const EnvironmentSample s = distribution.sample({stream.next(), stream.next()});
    ASSERT_GT(s.pdf, 0.0f);
    EXPECT_NEAR(distribution.pdf(s.direction), s.pdf, 1e-3f * s.pdf);
    expectNear(s.radiance, map.radiance(s.direction), 1e-6f * (1 + s.radiance.r));
  }
  EXPECT_TRUE(kFamily.chiSquare(
      [&](ref::SampleStream& r) {
        return distribution.sample({r.next(), r.next()}).direction;
      },
      [&](const glm::vec3& w) { return double(distribution.pdf(w)); }));
}

TEST(EnvironmentDistribution, SmoothRotatedMapMatchesItsDensity) {
  EnvironmentMap map =
      greyMap(32, [](int x, int y) { return 0.2 + std::pow(std::sin(0.1 * x + 0.2 * y), 2); });
  map.rotation_deg = 33.0f;
  expectSamplerMatchesDensity(map);
}

TEST(EnvironmentDistribution, BrightSpotMatchesItsDensity) {
  // A sun: a block of 8 × 4 texels near the zenith, where texels are small, six hundred times
  // brighter than the rest (the test integrates the density over its bins numerically, to 0.1%,
  // which the sharp edges of a smaller block would outrun).
  expectSamplerMatchesDensity(
      greyMap(32, [](int x, int y) { return x >= 8 && x < 16 && y >= 2 && y < 6 ? 30.0 : 0.05; }));
  // The test's power: the draws of a map turned by 20° do not follow this density.
  EnvironmentMap map =
      greyMap(32, [](int x, int y) { return x >= 8 && x < 16 && y >= 2 && y < 6 ? 30.0 : 0.05; });
  const EnvironmentDistribution density(map);
  map.rotation_deg = 20.0f;
  const EnvironmentDistribution turned(map);
  EXPECT_FALSE(kFamily.chiSquare(
      [&](ref::SampleStream& r) {
        return turned.sample({r.next(), r.next()}).direction;
      },
      [&](const glm::vec3& w) { return double(density.pdf(w)); }));
}

TEST(EnvironmentDistribution, DrawsInProportionToLuminanceTimesSolidAngle) {
  // Two lit texels of equal radiance at different latitudes: each is drawn in proportion to its
  // solid angle, so the one near the horizon far more often than the one near the pole.
  const int h = 8;
  const EnvironmentMap map =
      greyMap(h, [](int x, int y) { return (x == 3 && y == 0) || (x == 9 && y == 3) ? 1 : 0; });
  const EnvironmentDistribution distribution(map);
  constexpr std::size_t kDraws = 20000;
  std::size_t pole = 0;
  ref::SampleStream stream(11, 0, 0);
  for (std::size_t i = 0; i < kDraws; ++i) {
    const glm::vec2 uv =
        latLongCoordinates(distribution.sample({stream.next(), stream.next()}).direction);
    if (uv.y < 1.0f / h) ++pole;
  }
  // sin θ at the rows' centres: the distribution's weights (the texels' solid angles differ from
  // them by under 1%).
  const double pole_weight = std::sin(kPi * 0.5 / h), horizon_weight = std::sin(kPi * 3.5 / h);
  EXPECT_TRUE(kFamily.binomial(pole, kDraws, pole_weight / (pole_weight + horizon_weight)));
  EXPECT_TRUE(EnvironmentDistribution(greyMap(4, [](int, int) { return 0; })).black());
}

}  // namespace
}  // namespace gib::scene
