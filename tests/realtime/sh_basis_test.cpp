// The general real spherical-harmonic basis (realtime/sh/sh_basis.h) against answers computed
// another way: orthonormality by an exact product quadrature, closed forms from tables, the
// irradiance volume's bands 0–3, and refused band counts.
#include "realtime/sh/sh_basis.h"
#include "common/input_error.h"
#include "common/splitmix.h"
#include "realtime/sh/spherical_harmonics.h"
#include "support/gauss_legendre.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

namespace gib::rt::sh {
namespace {

constexpr double kPi = std::numbers::pi;

using test::gaussLegendre;
using test::QuadratureRule;

glm::dvec3 direction(double cos_theta, double phi) {
  const double s = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
  return {s * std::cos(phi), s * std::sin(phi), cos_theta};
}

// Uniform unit vectors from a SplitMix64 stream.
std::vector<glm::dvec3> randomDirections(int count, std::uint64_t seed) {
  std::vector<glm::dvec3> out;
  for (int i = 0; i < count; ++i) {
    const double u = double(splitMix64(seed + std::uint64_t(2 * i) * kGoldenGamma) >> 11) * 0x1p-53;
    const double v =
        double(splitMix64(seed + std::uint64_t(2 * i + 1) * kGoldenGamma) >> 11) * 0x1p-53;
    out.push_back(direction(2 * u - 1, 2 * kPi * v));
  }
  return out;
}

TEST(ShBasis, OrthonormalUpToEightBands) {
  // ∫ Y_a Y_b dω by 16 Gauss–Legendre nodes in cosθ times 32 equal steps in φ. Exact up to
  // rounding: the φ sum integrates cos/sin of frequency < 32 exactly, which kills every pair with
  // m_a ≠ m_b; for m_a = m_b the product is sin^{2m}θ times polynomials, a polynomial of degree
  // ≤ 14 in cosθ, and 16 nodes are exact to degree 31. So the tolerance is rounding's: 1e-12 for
  // the double basis, 2e-6 for the float one (its values carry ~1e-7 relative error).
  constexpr double kDoubleTolerance = 1e-12, kFloatTolerance = 2e-6;
  constexpr int kBands = kShBasisMaxBands, kCount = kBands * kBands, kPhi = 32;
  const QuadratureRule rule = gaussLegendre(16);
  std::vector<double> gram(kCount * kCount, 0.0), gram_float(kCount * kCount, 0.0);
  std::vector<double> y(kCount);
  std::vector<float> y_float(kCount);
  for (std::size_t q = 0; q < rule.x.size(); ++q)
    for (int k = 0; k < kPhi; ++k) {
      const glm::dvec3 d = direction(rule.x[q], 2 * kPi * (k + 0.5) / kPhi);
      const double weight = rule.w[q] * 2 * kPi / kPhi;
      evaluateShBasis(d, kBands, y);
      evaluateShBasis(glm::vec3(d), kBands, y_float);
      for (int a = 0; a < kCount; ++a)
        for (int b = 0; b < kCount; ++b) {
          gram[std::size_t(a * kCount + b)] += weight * y[std::size_t(a)] * y[std::size_t(b)];
          gram_float[std::size_t(a * kCount + b)] +=
              weight * double(y_float[std::size_t(a)]) * double(y_float[std::size_t(b)]);
        }
    }
  for (int a = 0; a < kCount; ++a)
    for (int b = 0; b < kCount; ++b) {
      const double expected = a == b ? 1.0 : 0.0;
      EXPECT_NEAR(gram[std::size_t(a * kCount + b)], expected, kDoubleTolerance) << a << "," << b;
      EXPECT_NEAR(gram_float[std::size_t(a * kCount + b)], expected, kFloatTolerance)
          << a << "," << b;
    }
}

TEST(ShBasis, MatchesClosedFormsOfBandsZeroToFourAndSeven) {
  // Tolerance: the closed forms are evaluated in double, the tables' constants are exact
  // expressions; what remains is rounding (1e-12 on values of order 1).
  constexpr double kTolerance = 1e-12;
  const double sqrt_pi = std::sqrt(kPi);
  std::vector<double> y(64);
  for (const glm::dvec3& d : randomDirections(50, 7)) {
    const double x = d.x, yy = d.y, z = d.z;
    evaluateShBasis(d, 8, y);
    // Bands 0–3: Sloan's table as the irradiance volume's GLSL keeps it, in exact form.
    const double expected[16] = {1 / (2 * sqrt_pi),
                                 std::sqrt(3 / (4 * kPi)) * yy,
                                 std::sqrt(3 / (4 * kPi)) * z,
                                 std::sqrt(3 / (4 * kPi)) * x,
                                 0.5 * std::sqrt(15 / kPi) * x * yy,
                                 0.5 * std::sqrt(15 / kPi) * yy * z,
                                 0.25 * std::sqrt(5 / kPi) * (3 * z * z - 1),
                                 0.5 * std::sqrt(15 / kPi) * x * z,
                                 0.25 * std::sqrt(15 / kPi) * (x * x - yy * yy),
                                 0.25 * std::sqrt(35 / (2 * kPi)) * yy * (3 * x * x - yy * yy),
                                 0.5 * std::sqrt(105 / kPi) * x * yy * z,
                                 0.25 * std::sqrt(21 / (2 * kPi)) * yy * (5 * z * z - 1),
                                 0.25 * std::sqrt(7 / kPi) * z * (5 * z * z - 3),
                                 0.25 * std::sqrt(21 / (2 * kPi)) * x * (5 * z * z - 1),
                                 0.25 * std::sqrt(105 / kPi) * z * (x * x - yy * yy),
                                 0.25 * std::sqrt(35 / (2 * kPi)) * x * (x * x - 3 * yy * yy)};
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(y[std::size_t(i)], expected[i], kTolerance) << i;
    // Band 4 (the standard table of real harmonics, e.g. Wikipedia "Table of spherical
    // harmonics"), index 16 + 4 + m.
    const double band4[9] = {0.75 * std::sqrt(35 / kPi) * x * yy * (x * x - yy * yy),
                             0.75 * std::sqrt(35 / (2 * kPi)) * (3 * x * x - yy * yy) * yy * z,
                             0.75 * std::sqrt(5 / kPi) * x * yy * (7 * z * z - 1),
                             0.75 * std::sqrt(5 / (2 * kPi)) * yy * z * (7 * z * z - 3),
                             3.0 / 16 / sqrt_pi * (35 * z * z * z * z - 30 * z * z + 3),
                             0.75 * std::sqrt(5 / (2 * kPi)) * x * z * (7 * z * z - 3),
                             3.0 / 8 * std::sqrt(5 / kPi) * (x * x - yy * yy) * (7 * z * z - 1),
                             0.75 * std::sqrt(35 / (2 * kPi)) * (x * x - 3 * yy * yy) * x * z,
                             3.0 / 16 * std::sqrt(35 / kPi) *
                                 (x * x * (x * x - 3 * yy * yy) - yy * yy * (3 * x * x - yy * yy))};
    for (int m = -4; m <= 4; ++m)
      EXPECT_NEAR(y[std::size_t(20 + m)], band4[m + 4], kTolerance) << "l=4 m=" << m;
    // Band 7: Y_7^0 = √(15/4π) P_7(z), P_7 = (429z⁷ − 693z⁵ + 315z³ − 35z)/16, and
    // Y_7^{±7} = √2·(3/64)√(715/2π)·sin⁷θ·(cos 7φ, sin 7φ) = ·(Re, Im)(x + iy)⁷.
    const double p7 =
        (429 * std::pow(z, 7) - 693 * std::pow(z, 5) + 315 * std::pow(z, 3) - 35 * z) / 16;
    EXPECT_NEAR(y[56], std::sqrt(15 / (4 * kPi)) * p7, kTolerance);
    const std::complex<double> power = std::pow(std::complex<double>(x, yy), 7);
    const double n77 = std::numbers::sqrt2 * 3.0 / 64 * std::sqrt(715 / (2 * kPi));
    EXPECT_NEAR(y[63], n77 * power.real(), kTolerance);
    EXPECT_NEAR(y[49], n77 * power.imag(), kTolerance);
  }
}

TEST(ShBasis, IrradianceVolumeBasisIsTheGeneralOneAndFloatMatchesDouble) {
  // evaluateBasis (bands 0–3) rounds the double basis: equal to the float recurrence within a
  // few float ulps (2e-7 on values ≤ 1.2). The float overload over 8 bands stays within 2e-6 of
  // the double one (values up to ~2.5, the recurrence adds a few roundings per band).
  constexpr double kUlps = 2e-7, kFloatRecurrence = 2e-6;
  std::vector<float> f(64);
  std::vector<double> d(64);
  for (const glm::dvec3& direction : randomDirections(200, 3)) {
    const auto fixed = evaluateBasis(glm::vec3(direction));
    evaluateShBasis(glm::vec3(direction), 8, f);
    evaluateShBasis(direction, 8, d);
    for (std::size_t i = 0; i < fixed.size(); ++i) EXPECT_NEAR(fixed[i], f[i], kUlps) << i;
    for (std::size_t i = 0; i < f.size(); ++i) EXPECT_NEAR(f[i], d[i], kFloatRecurrence) << i;
  }
  // Y_0^0 = 1/(2√π) and Y_1^0 = √(3/4π)·cosθ exactly at the pole.
  evaluateShBasis(glm::dvec3(0, 0, 1), 2, d);
  EXPECT_DOUBLE_EQ(d[0], 0.5 / std::sqrt(kPi));
  EXPECT_DOUBLE_EQ(d[2], std::sqrt(3 / (4 * kPi)));
}

TEST(ShBasis, BandsOutsideOneToEightAreRefused) {
  std::vector<float> out(100);
  EXPECT_THROW(evaluateShBasis(glm::vec3(0, 0, 1), 0, out), InputError);
  EXPECT_THROW(evaluateShBasis(glm::vec3(0, 0, 1), 9, out), InputError);
  std::vector<float> small(8);
  EXPECT_THROW(evaluateShBasis(glm::vec3(0, 0, 1), 3, small), std::invalid_argument);
}

}  // namespace
}  // namespace gib::rt::sh
