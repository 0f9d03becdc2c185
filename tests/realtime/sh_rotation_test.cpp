// Rotation of spherical-harmonic coefficients (realtime/sh/sh_rotation.h) against evaluation:
// the rotated coefficients of f reproduce f(R⁻¹ω) at random directions for bands 1..8; the band
// matrices are orthogonal and compose like the rotations; the cheap rotations about +z and +y
// agree with the general one.
#include "realtime/sh/sh_rotation.h"
#include "common/input_error.h"
#include "common/splitmix.h"
#include "realtime/sh/sh_basis.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <numbers>
#include <vector>

namespace gib::rt::sh {
namespace {

constexpr double kPi = std::numbers::pi;

class Stream {
 public:
  explicit Stream(std::uint64_t seed) : seed_(seed) {}
  double uniform() { return double(splitMix64(seed_ + counter_++ * kGoldenGamma) >> 11) * 0x1p-53; }
  double signedUniform() { return 2 * uniform() - 1; }

 private:
  std::uint64_t seed_, counter_ = 0;
};

// A uniformly random rotation: a quaternion drawn uniformly in the unit 4-ball (by rejection),
// normalised, as a double matrix.
glm::dmat3 randomRotation(Stream& stream) {
  glm::dquat q;
  do {
    q = glm::dquat(stream.signedUniform(), stream.signedUniform(), stream.signedUniform(),
                   stream.signedUniform());
  } while (glm::length(q) > 1 || glm::length(q) < 0.1);
  return glm::mat3_cast(glm::normalize(q));
}

glm::dvec3 randomDirection(Stream& stream) {
  const double z = stream.signedUniform(), phi = 2 * kPi * stream.uniform();
  const double s = std::sqrt(1 - z * z);
  return {s * std::cos(phi), s * std::sin(phi), z};
}

double evaluate(const std::vector<double>& c, const glm::dvec3& d, int bands) {
  std::vector<double> y(std::size_t(shBasisCount(bands)));
  evaluateShBasis(d, bands, y);
  double sum = 0;
  for (std::size_t i = 0; i < y.size(); ++i) sum += c[i] * y[i];
  return sum;
}

glm::dmat3 aboutZ(double a) {
  return glm::dmat3(glm::dvec3(std::cos(a), std::sin(a), 0),
                    glm::dvec3(-std::sin(a), std::cos(a), 0), glm::dvec3(0, 0, 1));
}
glm::dmat3 aboutY(double a) {  // +x towards −z
  return glm::dmat3(glm::dvec3(std::cos(a), 0, -std::sin(a)), glm::dvec3(0, 1, 0),
                    glm::dvec3(std::sin(a), 0, std::cos(a)));
}

TEST(ShRotation, RotatedCoefficientsReproduceTheRotatedFunction) {
  // Σ D(R)c · Y(ω) = Σ c · Y(R⁻¹ω) at 100 random directions, for random c (entries in [−1, 1])
  // and a random rotation per band count. In double the only error is rounding through the
  // recurrence (1e-11 of √Σc², the function's scale); through the float API (float matrix,
  // float coefficients) 1e-5 of it.
  constexpr double kDoubleTolerance = 1e-11, kFloatTolerance = 1e-5;
  Stream stream(2024);
  for (int bands = 1; bands <= kShBasisMaxBands; ++bands) {
    const auto count = std::size_t(shBasisCount(bands));
    std::vector<double> c(count), turned(count);
    double scale = 0;
    for (double& v : c) {
      v = stream.signedUniform();
      scale += v * v;
    }
    scale = std::sqrt(scale);
    const glm::dmat3 r = randomRotation(stream);
    ShRotation(r, bands).apply(c, turned);
    std::vector<float> c_float(c.begin(), c.end()), turned_float(count);
    ShRotation(glm::mat3(r), bands).apply(c_float, turned_float);
    const std::vector<double> turned_from_float(turned_float.begin(), turned_float.end());
    const glm::dmat3 inverse = glm::transpose(r);
    for (int k = 0; k < 100; ++k) {
      const glm::dvec3 d = randomDirection(stream);
      const double expected = evaluate(c, inverse * d, bands);
      EXPECT_NEAR(evaluate(turned, d, bands), expected, kDoubleTolerance * scale) << bands;
      EXPECT_NEAR(evaluate(turned_from_float, d, bands), expected, kFloatTolerance * scale)
          << bands;
    }
  }
}

TEST(ShRotation, BandMatricesAreOrthogonalAndCompose) {
  // D(R) is orthogonal per band, and D(R₁R₂) = D(R₁)D(R₂) (f ↦ f∘R⁻¹ is a representation).
  // Rounding only: 1e-12.
  constexpr double kTolerance = 1e-12;
  Stream stream(77);
  const glm::dmat3 r1 = randomRotation(stream), r2 = randomRotation(stream);
  const ShRotation a(r1, 8), b(r2, 8), ab(r1 * r2, 8);
  for (int l = 0; l < 8; ++l) {
    const int n = 2 * l + 1;
    const auto da = a.bandMatrix(l), db = b.bandMatrix(l), dab = ab.bandMatrix(l);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        double product = 0, gram = 0;
        for (int k = 0; k < n; ++k) {
          product += da[std::size_t(i * n + k)] * db[std::size_t(k * n + j)];
          gram += da[std::size_t(k * n + i)] * da[std::size_t(k * n + j)];
        }
        EXPECT_NEAR(product, dab[std::size_t(i * n + j)], kTolerance) << l;
        EXPECT_NEAR(gram, i == j ? 1.0 : 0.0, kTolerance) << l;
      }
  }
}

TEST(ShRotation, RotationsAboutZAndYAgreeWithTheGeneralOne) {
  // Float coefficients (entries in [−1, 1]) turned in place against the general rotation in
  // double: float rounding, 2e-6 per coefficient (the +y path multiplies two band matrices).
  constexpr double kTolerance = 2e-6;
  Stream stream(5);
  for (int bands : {1, 3, 6, 8}) {
    const auto count = std::size_t(shBasisCount(bands));
    std::vector<double> c(count), expected(count);
    for (double& v : c) v = stream.signedUniform();
    for (double angle : {0.3, -1.7, 2.9}) {
      std::vector<float> z(c.begin(), c.end()), y(c.begin(), c.end());
      rotateAboutZ(z, bands, float(angle));
      ShRotation(aboutZ(double(float(angle))), bands).apply(c, expected);
      for (std::size_t i = 0; i < count; ++i)
        EXPECT_NEAR(z[i], expected[i], kTolerance) << "z " << bands << " " << i;
      rotateAboutY(y, bands, float(angle));
      ShRotation(aboutY(double(float(angle))), bands).apply(c, expected);
      for (std::size_t i = 0; i < count; ++i)
        EXPECT_NEAR(y[i], expected[i], kTolerance) << "y " << bands << " " << i;
      // The RGB overloads turn each channel alike.
      std::vector<glm::vec3> rgb(count);
      for (std::size_t i = 0; i < count; ++i)
        rgb[i] = glm::vec3(float(c[i]), -float(c[i]), 0.5f * float(c[i]));
      rotateAboutY(rgb, bands, float(angle));
      for (std::size_t i = 0; i < count; ++i) {
        EXPECT_NEAR(rgb[i].x, expected[i], kTolerance);
        EXPECT_NEAR(rgb[i].y, -expected[i], kTolerance);
        EXPECT_NEAR(rgb[i].z, 0.5 * expected[i], kTolerance);
      }
    }
  }
}

TEST(ShRotation, IdentityKeepsCoefficientsAndBadBandsAreRefused) {
  std::vector<double> c(64), out(64);
  for (std::size_t i = 0; i < c.size(); ++i) c[i] = double(i) - 20.5;
  ShRotation(glm::dmat3(1.0), 8).apply(c, out);
  for (std::size_t i = 0; i < c.size(); ++i) EXPECT_NEAR(out[i], c[i], 1e-12) << i;
  EXPECT_THROW(ShRotation(glm::dmat3(1.0), 9), InputError);
  EXPECT_THROW(ShRotation(glm::dmat3(1.0), 0), InputError);
  std::vector<double> short_vector(8);
  EXPECT_THROW(ShRotation(glm::dmat3(1.0), 3).apply(short_vector, out), std::invalid_argument);
}

}  // namespace
}  // namespace gib::rt::sh
