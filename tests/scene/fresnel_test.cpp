// The Fresnel functions of scene/fresnel_shared.h against the book's eq. 1.5 evaluated with
// complex arithmetic (std::complex, an independent route to the same closed form), energy
// conservation at a dielectric interface, and eq. 1.6 at normal incidence. Deterministic: the
// tolerances are float rounding.
#include "scene/fresnel_shared.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

namespace gib::scene {
namespace {

using Complex = std::complex<double>;

// Eq. 1.5 as printed: ½(|(cos θ' − η cos θ)/(cos θ' + η cos θ)|² + |(cos θ − η cos θ')/(cos θ +
// η cos θ')|²), with η = n + iκ and cos θ = √(1 − sin²θ'/η²) complex (Snell's law with a complex
// index), the root with a non-negative real part.
double bookEquation15(double cos_i, Complex eta) {
  const double sin2_i = 1.0 - cos_i * cos_i;
  Complex cos_t = std::sqrt(1.0 - sin2_i / (eta * eta));
  if (cos_t.real() < 0) cos_t = -cos_t;
  const Complex s = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  const Complex p = (cos_t - eta * cos_i) / (cos_t + eta * cos_i);
  return 0.5 * (std::norm(s) + std::norm(p));
}

// Gold's index at three wavelengths (the values the GPU test uses too): any conductor will do.
const glm::vec3 kGoldN(0.18f, 0.42f, 1.37f);
const glm::vec3 kGoldK(3.42f, 2.35f, 1.77f);

TEST(Fresnel, DielectricMatchesEquation15AtEveryAngle) {
  for (float eta : {1.33f, 1.5f, 2.4f, 1.0f / 1.5f}) {
    for (int i = 0; i <= 1000; ++i) {
      const float cos_i = float(i) / 1000.0f;
      const double sin2_t = (1.0 - double(cos_i) * cos_i) / (double(eta) * eta);
      const double expected = sin2_t >= 1.0 ? 1.0 : bookEquation15(cos_i, Complex(eta, 0));
      EXPECT_NEAR(fresnelDielectric(cos_i, eta), expected, 2e-6)
          << "eta " << eta << ", cos " << cos_i;
    }
  }
}

TEST(Fresnel, ConductorMatchesEquation15AtEveryAngle) {
  for (int i = 0; i <= 1000; ++i) {
    const float cos_i = float(i) / 1000.0f;
    const glm::vec3 f = fresnelConductor(cos_i, kGoldN, kGoldK);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(f[c], bookEquation15(cos_i, Complex(kGoldN[c], kGoldK[c])), 2e-6)
          << "cos " << cos_i << ", channel " << c;
  }
}

TEST(Fresnel, ConductorWithoutExtinctionIsTheDielectric) {
  for (int i = 0; i <= 100; ++i) {
    const float cos_i = float(i) / 100.0f;
    EXPECT_NEAR(fresnelConductor(cos_i, glm::vec3(1.5f), glm::vec3(0.0f)).x,
                fresnelDielectric(cos_i, 1.5f), 2e-6);
  }
}

// What the interface transmits, from the transmitted amplitudes rather than from 1 − R:
// T = (η cos θt / cos θi)·|t|², t⊥ = 2cos θi/(cos θi + η cos θt), t∥ = 2cos θi/(η cos θi + cos θt).
// R + T = 1 checks the reflectance against a second physical quantity.
TEST(Fresnel, ReflectedAndTransmittedPowerAddUpToOne) {
  for (float eta : {1.5f, 1.0f / 1.5f}) {
    for (int i = 1; i <= 1000; ++i) {
      const double cos_i = double(i) / 1000.0;
      const double sin2_t = (1.0 - cos_i * cos_i) / (double(eta) * eta);
      if (sin2_t >= 1.0) {
        EXPECT_EQ(fresnelDielectric(float(cos_i), eta), 1.0f);  // total internal reflection
        continue;
      }
      const double cos_t = std::sqrt(1.0 - sin2_t);
      const double t_s = 2.0 * cos_i / (cos_i + eta * cos_t);
      const double t_p = 2.0 * cos_i / (eta * cos_i + cos_t);
      const double transmitted = eta * cos_t / cos_i * 0.5 * (t_s * t_s + t_p * t_p);
      EXPECT_NEAR(fresnelDielectric(float(cos_i), eta) + transmitted, 1.0, 1e-5)
          << "eta " << eta << ", cos " << cos_i;
    }
  }
}

TEST(Fresnel, Equation16IsExactAtNormalIncidenceAndApproximatesElsewhere) {
  const glm::vec3 f0 = fresnelAtNormalIncidence(kGoldN, kGoldK);
  const glm::vec3 exact = fresnelConductor(1.0f, kGoldN, kGoldK);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(f0[c], exact[c], 1e-6);
  // The approximation reaches 1 at grazing incidence like the exact function, and stays within
  // the few per cent its authors report for metals (Lazányi & Szirmay-Kalos 2005) in between.
  for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(fresnelApproximation(f0, 0.0f)[c], 1.0f);
  for (int i = 0; i <= 100; ++i) {
    const float cos_i = float(i) / 100.0f;
    const glm::vec3 approx = fresnelApproximation(f0, cos_i);
    const glm::vec3 f = fresnelConductor(cos_i, kGoldN, kGoldK);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(approx[c], f[c], 0.1) << "cos " << cos_i;
  }
}

}  // namespace
}  // namespace gib::scene
