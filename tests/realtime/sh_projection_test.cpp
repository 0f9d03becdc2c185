// The projection of a latitude–longitude map on spherical harmonics (realtime/sh/
// sh_projection.h) against answers computed another way: a constant map, a finely sampled
// band-limited map recovered, and the projection of random texels against a direct quadrature
// of the same texels in world directions.
#include "realtime/sh/sh_projection.h"
#include "common/input_error.h"
#include "common/splitmix.h"
#include "realtime/sh/sh_basis.h"
#include "scene/environment_map.h"
#include "support/gauss_legendre.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace gib::rt::sh {
namespace {

constexpr double kPi = std::numbers::pi;

// The map whose texel (x, y) holds radiance(centre direction in world coordinates).
template <class F>
scene::EnvironmentMap mapOf(int height, float rotation_deg, float intensity, F radiance) {
  const int width = 2 * height;
  std::vector<float> texels(std::size_t(3 * width * height));
  scene::EnvironmentMap shape;
  shape.rotation_deg = rotation_deg;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::vec3 map_direction =
          scene::latLongDirection({(x + 0.5f) / float(width), (y + 0.5f) / float(height)});
      const glm::dvec3 value = radiance(glm::dvec3(shape.toWorld(map_direction)));
      for (int c = 0; c < 3; ++c) texels[std::size_t(3 * (y * width + x) + c)] = float(value[c]);
    }
  scene::EnvironmentMap map = scene::makeEnvironmentMap(width, height, std::move(texels), "test");
  map.rotation_deg = rotation_deg;
  map.intensity = intensity;
  return map;
}

TEST(ShProjection, ConstantMapHasOnlyTheConstantTerm) {
  // ∫ L·Y_0^0 dω = L·4π/(2√π) = 2√π·L; every other Y integrates to 0 over the sphere, and
  // over whole rows the φ integrals of cos mφ, sin mφ vanish exactly: rounding only (1e-6 of c_0,
  // float outputs).
  constexpr double kRelative = 1e-6;
  const glm::dvec3 radiance(1.0, 2.0, 0.5);
  const float intensity = 1.5f;
  for (int height : {1, 8, 33}) {
    const scene::EnvironmentMap map =
        mapOf(height, 30.0f, intensity, [&](const glm::dvec3&) { return radiance; });
    const std::vector<glm::vec3> c = projectLatLong(map, 8);
    ASSERT_EQ(c.size(), 64u);
    for (int channel = 0; channel < 3; ++channel) {
      const double c0 = 2 * std::sqrt(kPi) * radiance[channel] * intensity;
      EXPECT_NEAR(c[0][channel], c0, kRelative * c0) << height;
      for (std::size_t i = 1; i < c.size(); ++i)
        EXPECT_NEAR(c[i][channel], 0.0, kRelative * c0) << height << " " << i;
    }
  }
}

TEST(ShProjection, RecoversABandLimitedFunctionSampledFinely) {
  // A map whose texels sample Σ c_i Y_i at their centres (|c_i| ≤ 1 beyond c_0), turned by 37°,
  // the channels scaled by 1, 2 and 0.5, intensity 2: its projection is intensity × scale × c up
  // to the texels' piecewise-constant approximation, a midpoint rule of second order. On 512
  // rows (Δ ≈ 0.006 rad) with bands up to l = 7 the error measured 7.5e-5 per unit of
  // intensity × scale; 1.5e-4 leaves a factor 2.
  constexpr double kTolerance = 1.5e-4;
  constexpr int kBands = 8;
  std::vector<double> coefficients(64);
  for (std::size_t i = 0; i < coefficients.size(); ++i)
    coefficients[i] = double(splitMix64(99 + i) >> 11) * 0x1p-53 * 2 - 1;
  // Radiance must be ≥ 0: by the addition theorem |Σ_{l≥1} c_i Y_i| ≤ Σ_l (2l+1)/√(4π) < 18
  // for |c_i| ≤ 1, and c_0·Y_0^0 = 80/(2√π) ≈ 22.6 lifts it above 0.
  coefficients[0] = 80;
  const scene::EnvironmentMap map = mapOf(512, 37.0f, 2.0f, [&](const glm::dvec3& d) {
    std::vector<double> y(64);
    evaluateShBasis(d, kBands, y);
    double sum = 0;
    for (std::size_t i = 0; i < y.size(); ++i) sum += coefficients[i] * y[i];
    return glm::dvec3(sum, 2 * sum, 0.5 * sum);
  });
  const std::vector<glm::vec3> c = projectLatLong(map, kBands);
  for (std::size_t i = 0; i < c.size(); ++i) {
    EXPECT_NEAR(c[i].x, 2 * coefficients[i], 2 * kTolerance) << i;
    EXPECT_NEAR(c[i].y, 4 * coefficients[i], 4 * kTolerance) << i;
    EXPECT_NEAR(c[i].z, coefficients[i], kTolerance) << i;
  }
}

TEST(ShProjection, IsExactForTheTexelsAgainstADirectQuadrature) {
  // Random texels on a coarse map (8 rows, so the rows are split; rotation 23°, intensity 0.7):
  // the projection against an independent quadrature of the same texels that never leaves the
  // world frame: per texel 16 × 16 Gauss–Legendre nodes in φ and θ with the Jacobian sinθ,
  // directions turned into the world in double by R_y (scene/environment_map.h's convention,
  // checked against map.toWorld), the world basis evaluated there. Both are exact to rounding
  // for these smooth integrands, so they agree to the float outputs' precision (1e-6 of the
  // largest coefficient).
  constexpr double kRelative = 1e-6;
  constexpr int kBands = 8, kHeight = 8, kWidth = 16;
  std::vector<float> texels(3 * kWidth * kHeight);
  for (std::size_t i = 0; i < texels.size(); ++i)
    texels[i] = float(double(splitMix64(5 + i) >> 11) * 0x1p-53);
  scene::EnvironmentMap map = scene::makeEnvironmentMap(kWidth, kHeight, texels, "random");
  map.rotation_deg = 23.0f;
  map.intensity = 0.7f;
  const double a = double(map.rotation_deg) * kPi / 180;
  auto to_world = [&](const glm::dvec3& d) {  // +x towards −z for a positive angle
    return glm::dvec3(std::cos(a) * d.x + std::sin(a) * d.z, d.y,
                      -std::sin(a) * d.x + std::cos(a) * d.z);
  };
  const glm::vec3 probe = glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f));
  ASSERT_LT(glm::length(glm::dvec3(map.toWorld(probe)) - to_world(glm::dvec3(probe))), 1e-6);

  const test::QuadratureRule rule = test::gaussLegendre(16);
  std::vector<glm::dvec3> expected(64, glm::dvec3(0.0));
  std::vector<double> y(64);
  for (int row = 0; row < kHeight; ++row)
    for (int column = 0; column < kWidth; ++column) {
      const glm::dvec3 texel = glm::dvec3(map.texel(column, row)) * double(map.intensity);
      const double theta0 = kPi * row / kHeight, dtheta = kPi / kHeight;
      const double phi0 = 2 * kPi * column / kWidth, dphi = 2 * kPi / kWidth;
      for (std::size_t i = 0; i < rule.x.size(); ++i)
        for (std::size_t j = 0; j < rule.x.size(); ++j) {
          const double theta = theta0 + dtheta * 0.5 * (1 + rule.x[i]);
          const double phi = phi0 + dphi * 0.5 * (1 + rule.x[j]);
          const double weight = 0.25 * dtheta * dphi * rule.w[i] * rule.w[j] * std::sin(theta);
          // The map's direction at (θ, φ): (sinθ cosφ, cosθ, sinθ sinφ).
          const glm::dvec3 map_direction(std::sin(theta) * std::cos(phi), std::cos(theta),
                                         std::sin(theta) * std::sin(phi));
          evaluateShBasis(to_world(map_direction), kBands, y);
          for (std::size_t k = 0; k < y.size(); ++k) expected[k] += weight * y[k] * texel;
        }
    }
  const std::vector<glm::vec3> c = projectLatLong(map, kBands);
  double largest = 0;
  for (const glm::dvec3& e : expected)
    largest = std::max({largest, std::abs(e.x), std::abs(e.y), std::abs(e.z)});
  for (std::size_t k = 0; k < c.size(); ++k)
    for (int channel = 0; channel < 3; ++channel)
      EXPECT_NEAR(c[k][channel], expected[k][channel], kRelative * largest) << k << " " << channel;
}

TEST(ShProjection, EmptyMapsAndBadBandsAreRefused) {
  EXPECT_THROW(projectLatLong(scene::EnvironmentMap{}, 3), InputError);
  const scene::EnvironmentMap map =
      mapOf(2, 0.0f, 1.0f, [](const glm::dvec3&) { return glm::dvec3(1.0); });
  EXPECT_THROW(projectLatLong(map, 0), InputError);
  EXPECT_THROW(projectLatLong(map, 9), InputError);
}

}  // namespace
}  // namespace gib::rt::sh
