#include "support/chi_square.h"

#include "metrics/distributions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace gib::test {

namespace {

constexpr int kCosThetaBins = 64;
constexpr int kPhiBins = 32;
constexpr double kMinExpected = 5;  // the usual validity condition of the chi-square statistic

int binOf(const glm::vec3& w) {
  double cos_theta = std::clamp(double(w.z), -1.0, 1.0);
  int i = std::min(int((cos_theta + 1.0) * 0.5 * kCosThetaBins), kCosThetaBins - 1);
  double phi = std::atan2(double(w.y), double(w.x));
  if (phi < 0) phi += 2 * std::numbers::pi;
  int j = std::min(int(phi / (2 * std::numbers::pi) * kPhiBins), kPhiBins - 1);
  return i * kPhiBins + j;
}

// Expected probability of each bin: the density integrated over (cos θ, φ) with a midpoint rule
// (the area element on the sphere is d(cos θ) dφ). The cos θ steps are fine enough to resolve a
// Phong lobe of exponent 100, whose width in cos θ is about 1/101.
std::vector<double> expectedProbabilities(const DirectionPdf& pdf) {
  constexpr int kSubZ = 64;
  constexpr int kSubPhi = 12;
  std::vector<double> p(kCosThetaBins * kPhiBins, 0.0);
  const double dz = 2.0 / kCosThetaBins / kSubZ;
  const double dphi = 2 * std::numbers::pi / kPhiBins / kSubPhi;
  for (int i = 0; i < kCosThetaBins * kSubZ; ++i)
    for (int j = 0; j < kPhiBins * kSubPhi; ++j) {
      double z = -1.0 + (i + 0.5) * dz;
      double phi = (j + 0.5) * dphi;
      double r = std::sqrt(std::max(0.0, 1 - z * z));
      glm::vec3 w(r * std::cos(phi), r * std::sin(phi), z);
      p[(i / kSubZ) * kPhiBins + j / kSubPhi] += pdf(w) * dz * dphi;
    }
  return p;
}

}  // namespace

double chiSquarePValue(const DirectionSampler& sample, const DirectionPdf& pdf) {
  std::vector<double> observed(kCosThetaBins * kPhiBins, 0.0);
  for (int s = 0; s < kChiSquareSamples; ++s) {
    ref::SampleStream random(99, 0, std::uint32_t(s));
    observed[binOf(sample(random))] += 1;
  }
  std::vector<double> expected = expectedProbabilities(pdf);
  double total = 0;
  for (double& e : expected) {
    total += e;
    e *= kChiSquareSamples;
  }
  EXPECT_NEAR(total, 1.0, 1e-3) << "the density does not integrate to one";

  return chiSquarePValue(observed, expected);
}

double chiSquarePValue(const std::vector<double>& observed, const std::vector<double>& expected) {
  // Pool the sparse bins into one so every cell meets the validity condition.
  double chi2 = 0, pooled_observed = 0, pooled_expected = 0;
  int cells = 0;
  for (std::size_t b = 0; b < observed.size(); ++b) {
    if (expected[b] < kMinExpected) {
      pooled_observed += observed[b];
      pooled_expected += expected[b];
      continue;
    }
    chi2 += (observed[b] - expected[b]) * (observed[b] - expected[b]) / expected[b];
    ++cells;
  }
  if (pooled_expected > 0) {
    chi2 += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) /
            std::max(pooled_expected, 1e-9);
    ++cells;
  }
  return metrics::chiSquareSurvival(chi2, cells - 1);
}

}  // namespace gib::test
