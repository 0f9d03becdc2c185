// The irradiance volume's spherical-harmonic arithmetic against closed forms: the basis is
// orthonormal, eq. 2 over cube faces recovers the coefficients of a constant and of a clamped
// cosine lobe, and eq. 4's Lambert transfer of a constant environment is ρ·L.
#include "realtime/sh/spherical_harmonics.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace gib::rt::sh {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(SphericalHarmonics, CubeTexelSolidAnglesCoverTheSphere) {
  for (int size : {1, 8, 16}) {
    double total = 0;
    for (int face = 0; face < 6; ++face)
      for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) total += cubeTexelSolidAngle(i, j, size);
    EXPECT_NEAR(total, 4 * kPi, 1e-9) << size;
  }
  // A face's centre texel of a 1-texel face sees a sixth of the sphere.
  EXPECT_NEAR(cubeTexelSolidAngle(0, 0, 1), 4 * kPi / 6, 1e-12);
}

TEST(SphericalHarmonics, BasisIsOrthonormalUnderCubeQuadrature) {
  // ∫ Y_a Y_b dω by eq. 2's weights on 64² faces: δ_ab within the quadrature's error.
  const int size = 64;
  for (int a = 0; a < kShMaxCoefficients; ++a)
    for (int b = a; b < kShMaxCoefficients; ++b) {
      const std::vector<double> c = projectOnCube(
          [&](const glm::vec3& d) { return glm::dvec3(evaluateBasis(d)[std::size_t(b)]); }, size,
          kShMaxBand, 0);
      EXPECT_NEAR(c[std::size_t(a)], a == b ? 1.0 : 0.0, 2e-3) << a << "," << b;
    }
}

TEST(SphericalHarmonics, ProjectionRecoversAConstantAndAClampedCosine) {
  // A constant 1: c_0 = √(4π), all others 0.
  const std::vector<double> constant =
      projectOnCube([](const glm::vec3&) { return glm::dvec3(1.0); }, 32, 3, 0);
  EXPECT_NEAR(constant[0], std::sqrt(4 * kPi), 1e-6);
  for (std::size_t i = 1; i < constant.size(); ++i) EXPECT_NEAR(constant[i], 0.0, 1e-6) << i;
  // max(cos θ, 0) about +z: c_0 = √π/2, c_(1,0) = √(π/3), c_(2,0) = √(5π)/8, c_(3,0) = 0, and
  // every m ≠ 0 vanishes by symmetry (Ramamoorthi & Hanrahan 2001).
  const std::vector<double> lobe =
      projectOnCube([](const glm::vec3& d) { return glm::dvec3(std::max(0.0f, d.z)); }, 64, 3, 1);
  const double expected[kShMaxCoefficients] = {std::sqrt(kPi) / 2,
                                               0,
                                               std::sqrt(kPi / 3),
                                               0,
                                               0,
                                               0,
                                               std::sqrt(5 * kPi) / 8,
                                               0,
                                               0,
                                               0,
                                               0,
                                               0,
                                               0,
                                               0,
                                               0,
                                               0};
  for (std::size_t i = 0; i < lobe.size(); ++i) EXPECT_NEAR(lobe[i], expected[i], 2e-3) << i;
}

TEST(SphericalHarmonics, ProjectionWeightsAreTheBasisTimesSolidAngle) {
  const int size = 4, band = 2, count = shCoefficientCount(band);
  const std::vector<float> weights = cubeProjectionWeights(size, band);
  ASSERT_EQ(weights.size(), std::size_t(6 * size * size * count));
  const int face = 3, i = 1, j = 2;
  const auto y = evaluateBasis(cubeTexelDirection(face, i, j, size));
  for (int c = 0; c < count; ++c)
    EXPECT_FLOAT_EQ(weights[std::size_t(((face * size + j) * size + i) * count + c)],
                    float(y[std::size_t(c)] * cubeTexelSolidAngle(i, j, size)));
  EXPECT_THROW(cubeProjectionWeights(4, 4), std::invalid_argument);
}

TEST(SphericalHarmonics, LambertTransferOfAConstantEnvironmentIsAlbedoTimesRadiance) {
  const double radiance = 2.5, albedo = 0.6;
  const std::vector<double> c =
      projectOnCube([&](const glm::vec3&) { return glm::dvec3(radiance); }, 16, 2, 0);
  const auto factors = lambertBandFactors();
  for (const glm::vec3 normal : {glm::vec3(0, 0, 1), glm::normalize(glm::vec3(1, -2, 0.5f))}) {
    const auto y = evaluateBasis(normal);
    double reflected = 0;
    for (int i = 0; i < shCoefficientCount(2); ++i)
      reflected += albedo *
                   factors[i < 1   ? 0
                           : i < 4 ? 1
                                   : 2] *
                   c[std::size_t(i)] * y[std::size_t(i)];
    EXPECT_NEAR(reflected, albedo * radiance, 1e-6);
  }
}

TEST(SphericalHarmonics, ZonalFactorsMatchEquationSixAndNarrowPhongLobes) {
  // Eq. 6's closed form is the quadrature of the Lambert lobe cos θ/π.
  const auto quadrature = zonalBandFactors([](double c) { return c / kPi; });
  const auto closed = lambertBandFactors();
  for (int l = 0; l <= kShMaxBand; ++l) EXPECT_NEAR(quadrature[l], closed[l], 1e-6) << l;
  // A normalised lobe keeps its energy (band 0 factor 1); as it narrows it passes every band.
  for (double n : {0.0, 1.0, 10.0, 100.0}) EXPECT_NEAR(phongBandFactors(n)[0], 1.0, 1e-5) << n;
  EXPECT_GT(phongBandFactors(2000)[3], 0.98f);
  EXPECT_LT(phongBandFactors(1)[2], phongBandFactors(50)[2]);
  EXPECT_THROW(phongBandFactors(-1), std::invalid_argument);
}

}  // namespace
}  // namespace gib::rt::sh
