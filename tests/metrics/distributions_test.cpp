#include "metrics/distributions.h"

#include <gtest/gtest.h>

#include <cmath>

namespace gib::metrics {
namespace {

TEST(Distributions, ChiSquareSurvivalMatchesClosedForms) {
  // χ²(2): P(X ≥ x) = e^{−x/2}.
  for (double x : {0.1, 1.0, 5.0, 20.0})
    EXPECT_NEAR(chiSquareSurvival(x, 2), std::exp(-x / 2), 1e-12);
  // χ²(1): P(X ≥ x) = erfc(√(x/2)).
  for (double x : {0.01, 0.5, 3.84, 10.0})
    EXPECT_NEAR(chiSquareSurvival(x, 1), std::erfc(std::sqrt(x / 2)), 1e-10);
  // Textbook critical value: χ²(10) at 23.209 has p = 0.01.
  EXPECT_NEAR(chiSquareSurvival(23.209, 10), 0.01, 1e-4);
  // Large dof (the chi-square tests use ~1000 cells): the mean has p ≈ 0.5.
  EXPECT_NEAR(chiSquareSurvival(1000, 1000), 0.494, 0.002);
}

TEST(Distributions, NormalQuantileInvertsTheCdf) {
  for (double p : {1e-10, 1e-4, 0.01, 0.3, 0.5, 0.9, 0.999, 1 - 1e-9})
    EXPECT_NEAR(normalCdf(normalQuantile(p)), p, 1e-12 + 1e-9 * p);
  EXPECT_NEAR(normalQuantile(0.975), 1.959963984540054, 1e-9);
}

TEST(Distributions, SidakCorrectionKeepsTheFamilyRate) {
  double alpha = sidakSignificance(0.01, 100);
  EXPECT_NEAR(1 - std::pow(1 - alpha, 100), 0.01, 1e-12);
  EXPECT_LT(alpha, 0.01 / 100 * 1.01);
}

}  // namespace
}  // namespace gib::metrics

namespace gib::metrics {
namespace {

TEST(Distributions, IncompleteBetaMatchesBinomialTails) {
  // For integers, I_x(a, b) = P(Binomial(a + b − 1, x) ≥ a).
  EXPECT_NEAR(regularizedBetaI(2, 3, 0.5), 11.0 / 16.0, 1e-14);
  EXPECT_NEAR(regularizedBetaI(1, 1, 0.3), 0.3, 1e-14);
  EXPECT_NEAR(regularizedBetaI(5, 2, 0.9), 0.885735, 1e-6);
  EXPECT_EQ(regularizedBetaI(3, 4, 0.0), 0.0);
  EXPECT_EQ(regularizedBetaI(3, 4, 1.0), 1.0);
  EXPECT_THROW(regularizedBetaI(0, 1, 0.5), std::domain_error);
}

TEST(Distributions, StudentTMatchesTablesAndTheNormalLimit) {
  // Two-sided 5% and 1% critical values of the usual tables.
  EXPECT_NEAR(studentTQuantile(0.975, 1), 12.7062, 1e-4);
  EXPECT_NEAR(studentTQuantile(0.975, 10), 2.2281, 1e-4);
  EXPECT_NEAR(studentTQuantile(0.995, 5), 4.0321, 1e-4);
  EXPECT_NEAR(studentTQuantile(0.975, 1e7), normalQuantile(0.975), 1e-5);
  EXPECT_NEAR(studentTCdf(0.0, 3), 0.5, 1e-15);
  EXPECT_NEAR(studentTCdf(-2.0, 4) + studentTCdf(2.0, 4), 1.0, 1e-14);
  for (double p : {0.01, 0.2, 0.5, 0.9, 0.999})
    EXPECT_NEAR(studentTCdf(studentTQuantile(p, 7), 7), p, 1e-12) << p;
}

}  // namespace
}  // namespace gib::metrics
