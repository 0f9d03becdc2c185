// The Preetham sky (scene/preetham_sky.h) against the paper's formulas evaluated here, the Perez
// distribution's shape, the map's symmetry and the sun's and ground's energy.
#include "scene/preetham_sky.h"
#include "common/input_error.h"
#include "common/luminance_shared.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace gib::scene {
namespace {

constexpr double kPi = std::numbers::pi;

double luminance(const Rgb& c) {
  return kLuminanceRed * c.r + kLuminanceGreen * c.g + kLuminanceBlue * c.b;
}

double radians(double degrees) {
  return degrees * kPi / 180.0;
}

// Texels are floats: sums of a few thousand of them agree to about 1e-6; 1e-5 leaves room.
constexpr double kFloatTolerance = 1e-5;

TEST(PreethamSky, PerezAtTheZenithGivesTheZenithValues) {
  for (float turbidity : {2.0f, 3.0f, 7.5f, 10.0f})
    for (float elevation : {0.0f, 15.0f, 30.0f, 75.0f, 90.0f}) {
      const PreethamSky sky({elevation, 40.0f, turbidity, 16});
      const glm::dvec3 zenith = sky.yxy({0.0, 1.0, 0.0});
      const double theta_s = radians(90.0 - elevation);
      const glm::dvec2 xy = zenithChromaticity(turbidity, theta_s);
      EXPECT_NEAR(zenith.x / zenithLuminanceKcd(turbidity, theta_s), 1.0, 1e-12);
      EXPECT_NEAR(zenith.y / xy.x, 1.0, 1e-12);
      EXPECT_NEAR(zenith.z / xy.y, 1.0, 1e-12);
    }
}

TEST(PreethamSky, ZenithLuminanceIsThePapersFormula) {
  // Preetham et al. 1999, Appendix A.2, written out again: T = 3, sun 60° from the zenith.
  const double t = 3.0, theta_s = radians(60.0);
  const double chi = (4.0 / 9.0 - t / 120.0) * (kPi - 2.0 * theta_s);
  const double expected = (4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192;
  EXPECT_NEAR(zenithLuminanceKcd(t, theta_s), expected, 1e-12);
  EXPECT_GT(expected, 0.0);
}

TEST(PreethamSky, ZenithChromaticityIsThePublishedMatrices) {
  // x_z = [T² T 1] M_x [θ³ θ² θ 1]ᵀ, y_z likewise (Appendix A.2), at T = 4, θ_s = 45°.
  const double t = 4.0, th = radians(45.0);
  const double x = t * t * (0.00166 * th * th * th - 0.00375 * th * th + 0.00209 * th) +
                   t * (-0.02903 * th * th * th + 0.06377 * th * th - 0.03202 * th + 0.00394) +
                   (0.11693 * th * th * th - 0.21196 * th * th + 0.06052 * th + 0.25886);
  const double y = t * t * (0.00275 * th * th * th - 0.00610 * th * th + 0.00317 * th) +
                   t * (-0.04214 * th * th * th + 0.08970 * th * th - 0.04153 * th + 0.00516) +
                   (0.15346 * th * th * th - 0.26756 * th * th + 0.06670 * th + 0.26688);
  const glm::dvec2 xy = zenithChromaticity(t, th);
  EXPECT_NEAR(xy.x, x, 1e-12);
  EXPECT_NEAR(xy.y, y, 1e-12);
  // A clear sky's zenith is bluish: below the D65 white's (0.3127, 0.3290).
  EXPECT_LT(x, 0.3127);
  EXPECT_LT(y, 0.3290);
}

TEST(PreethamSky, MapIsMirrorSymmetricAboutTheSunsVerticalPlane) {
  // Sun at φ = 90°, a column boundary: column x mirrors to column width/2 − 1 − x.
  const EnvironmentMap map = makePreethamSky({40.0f, 90.0f, 4.0f, 32}, SunDisc::kOmitted);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      const int mirror = ((map.width / 2 - 1 - x) % map.width + map.width) % map.width;
      const Rgb a = map.texel(x, y), b = map.texel(mirror, y);
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(a[c], b[c], kFloatTolerance * std::max(1.0f, a[c])) << x << ", " << y;
    }
}

TEST(PreethamSky, SkyBrightensTowardsTheSunAndTheHorizon) {
  const SkyParameters p{30.0f, 0.0f, 3.0f, 64};
  const EnvironmentMap map = makePreethamSky(p, SunDisc::kOmitted);
  const int sun_row = int(std::floor((90.0 - p.sun_elevation_deg) / 180.0 * map.height));
  // Along the sun's row, away from the sun (column 0 starts at its azimuth) up to 90° of azimuth.
  for (int x = 1; x <= map.width / 4; ++x)
    EXPECT_LT(luminance(map.texel(x, sun_row)), luminance(map.texel(x - 1, sun_row))) << x;
  // Down the sun's column from the zenith to the sun.
  for (int y = 1; y <= sun_row; ++y)
    EXPECT_GT(luminance(map.texel(0, y)), luminance(map.texel(0, y - 1))) << y;
  // In every azimuth the row above the horizon outshines the row at the zenith (the gradation
  // term 1 + A e^{B/cos θ} grows to 1 at the horizon).
  for (int x = 0; x < map.width; ++x)
    EXPECT_GT(luminance(map.texel(x, map.height / 2 - 1)), luminance(map.texel(x, 0))) << x;
}

TEST(PreethamSky, SunTexelHoldsTheSunsPower) {
  const SkyParameters p{35.0f, 123.0f, 4.0f, 64};
  const Rgb with = environmentIntegral(makePreethamSky(p));
  const Rgb without = environmentIntegral(makePreethamSky(p, SunDisc::kOmitted));
  const double sun_solid_angle = 2 * kPi * (1.0 - std::cos(radians(0.2667)));
  const Rgb l_sun = sunRadiance(p.turbidity, radians(90.0 - p.sun_elevation_deg));
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(double(with[c]) - without[c], l_sun[c] * sun_solid_angle,
                kFloatTolerance * with[c]);
  // The brightest texel is where the header's convention puts the sun: column ⌊φ_s/360° · width⌋,
  // row ⌊θ_s/180° · height⌋.
  const EnvironmentMap map = makePreethamSky(p);
  int brightest_x = 0, brightest_y = 0;
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x)
      if (luminance(map.texel(x, y)) > luminance(map.texel(brightest_x, brightest_y))) {
        brightest_x = x;
        brightest_y = y;
      }
  EXPECT_EQ(brightest_x, int(p.sun_azimuth_deg / 360.0 * map.width));
  EXPECT_EQ(brightest_y, int((90.0 - p.sun_elevation_deg) / 180.0 * map.height));
  // And a ray towards the sun finds it: far brighter than any sky.
  EXPECT_GT(luminance(map.radiance(glm::vec3(sunDirection(p)))),
            1000.0 * zenithLuminanceKcd(p.turbidity, radians(55.0)));
}

TEST(PreethamSky, SunIlluminanceIsPhysical) {
  // Normal illuminance of the overhead sun in the clearest sky: below the solar illuminance
  // constant, 133.8 klx outside the atmosphere (Darula, Kittler & Gueymard 2005), and above
  // 80 klx, a low figure for clear-sky direct normal illuminance at sea level.
  const double klx = luminance(sunRadiance(2.0, 0.0)) * sunSolidAngle();
  EXPECT_LT(klx, 133.8);
  EXPECT_GT(klx, 80.0);
  // More air and more haze both dim it (every transmittance decreases with either).
  EXPECT_LT(luminance(sunRadiance(2.0, radians(60.0))), luminance(sunRadiance(2.0, 0.0)));
  EXPECT_LT(luminance(sunRadiance(6.0, 0.0)), luminance(sunRadiance(2.0, 0.0)));
  // At sunset the blue goes first: the sun reddens.
  const Rgb low = sunRadiance(3.0, radians(88.0));
  EXPECT_GT(low.r, low.b);
}

TEST(PreethamSky, GroundIsAlbedoTimesHorizontalIrradianceOverPi) {
  // The irradiance of the model (not of the map's texels) by a finer midpoint rule.
  const SkyParameters p{45.0f, 10.0f, 3.0f, 32};
  const PreethamSky sky(p);
  const int n_theta = 256, n_phi = 512;
  glm::dvec3 e(0.0);
  for (int i = 0; i < n_theta; ++i) {
    const double theta = (i + 0.5) / n_theta * kPi / 2;
    const double weight =
        std::cos(theta) * std::sin(theta) * (kPi / 2 / n_theta) * (2 * kPi / n_phi);
    for (int j = 0; j < n_phi; ++j) {
      const double phi = (j + 0.5) / n_phi * 2 * kPi;
      const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::cos(theta),
                         std::sin(theta) * std::sin(phi));
      e += weight * glm::dvec3(sky.radiance(d));
    }
  }
  e += glm::dvec3(sunRadiance(p.turbidity, sky.sunTheta())) * sunSolidAngle() *
       std::cos(sky.sunTheta());
  const EnvironmentMap map = makePreethamSky(p);
  // The map's rows are 5.6° tall: its sky's irradiance differs from the model's by under 2 %.
  for (int c = 0; c < 3; ++c) {
    const double expected = 0.2 * e[c] / kPi;
    EXPECT_NEAR(map.texel(0, map.height - 1)[c], expected, 0.02 * expected);
    EXPECT_EQ(map.texel(17, map.height / 2)[c], map.texel(0, map.height - 1)[c]);
  }
}

TEST(PreethamSky, EveryFittedSkyStaysInsideTheRec709Gamut) {
  // A negative channel would be clamped and change the luminance: it does not, anywhere.
  for (float turbidity : {2.0f, 3.0f, 6.0f, 10.0f})
    for (float elevation : {0.0f, 5.0f, 30.0f, 60.0f, 90.0f}) {
      const PreethamSky sky({elevation, 0.0f, turbidity, 16});
      for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 16; ++j) {
          const double theta = (i + 0.5) / 8 * kPi / 2, phi = (j + 0.5) / 16 * 2 * kPi;
          const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::cos(theta),
                             std::sin(theta) * std::sin(phi));
          const double y = sky.yxy(d).x;
          ASSERT_GT(y, 0.0);
          ASSERT_NEAR(luminance(sky.radiance(d)), y, 1e-3 * y)
              << "T " << turbidity << ", elevation " << elevation << ", " << i << ", " << j;
        }
    }
}

TEST(PreethamSky, SourceNamesTheParameters) {
  EXPECT_EQ(makePreethamSky({30.0f, 0.0f, 3.0f, 8}).source,
            "preetham sky (sun elevation 30°, azimuth 0°, turbidity 3)");
}

TEST(PreethamSky, RefusesParametersOutsideTheFittedRange) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const SkyParameters bad[] = {{-0.1f, 0, 3, 128}, {90.1f, 0, 3, 128},  {nan, 0, 3, 128},
                               {30, inf, 3, 128},  {30, 0, 1.99f, 128}, {30, 0, 10.01f, 128},
                               {30, 0, nan, 128},  {30, 0, 3, 2},       {30, 0, 3, 5},
                               {30, 0, 3, 4098}};
  for (const SkyParameters& p : bad) EXPECT_THROW(validateSkyParameters(p), InputError);
  const SkyParameters good[] = {{0, -720, 2, 4}, {90, 359, 10, 4096}};
  for (const SkyParameters& p : good) EXPECT_NO_THROW(validateSkyParameters(p));
}

}  // namespace
}  // namespace gib::scene
