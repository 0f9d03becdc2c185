#include "support/statistical_test.h"

#include "metrics/distributions.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <string>

namespace gib::test {

namespace {

constexpr int kChiSquareSamples = 1000000;
constexpr int kCosThetaBins = 64;
constexpr int kPhiBins = 32;
constexpr double kMinExpected = 5;      // the usual validity condition of the chi-square statistic
constexpr std::size_t kCellsShown = 8;  // the chi-square table's rows: the largest contributions

// The test's verdict, with its table as the message either way (EXPECT_FALSE prints it too).
::testing::AssertionResult verdict(bool passed, const std::string& table) {
  return (passed ? ::testing::AssertionSuccess() : ::testing::AssertionFailure()) << table;
}

std::string familyLine(const TestFamily& family) {
  return fmt::format("level {:.3g} (family significance {:g} over {} tests, Šidák)", family.level(),
                     family.significance(), family.tests());
}

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

struct Cell {
  std::string name;
  double observed = 0, expected = 0, contribution = 0;
};

}  // namespace

double TestFamily::level() const {
  return metrics::sidakSignificance(significance_, tests_);
}

::testing::AssertionResult TestFamily::chiSquare(const std::vector<double>& observed,
                                                 const std::vector<double>& expected) const {
  if (observed.size() != expected.size())
    return ::testing::AssertionFailure()
           << "chi-square test of " << observed.size() << " observed counts against "
           << expected.size() << " expected ones: give one expected count per cell";
  // Pool the sparse cells into one so every cell meets the validity condition.
  std::vector<Cell> cells;
  Cell pooled{"pooled", 0, 0, 0};
  for (std::size_t b = 0; b < observed.size(); ++b) {
    if (expected[b] < kMinExpected) {
      pooled.observed += observed[b];
      pooled.expected += expected[b];
      continue;
    }
    const double d = observed[b] - expected[b];
    cells.push_back({std::to_string(b), observed[b], expected[b], d * d / expected[b]});
  }
  if (pooled.expected > 0) {
    const double d = pooled.observed - pooled.expected;
    pooled.contribution = d * d / std::max(pooled.expected, 1e-9);
    cells.push_back(pooled);
  }
  if (cells.size() < 2)
    return ::testing::AssertionFailure()
           << "chi-square test with " << cells.size()
           << " cell(s) of expected count 5 or more: give the test more samples or fewer cells";
  double chi2 = 0;
  for (const Cell& c : cells) chi2 += c.contribution;
  const double dof = double(cells.size() - 1);
  const double p_value = metrics::chiSquareSurvival(chi2, dof);

  std::string table = fmt::format(
      "chi-square {:.6g} over {} degrees of freedom ({} cells, those expected below {:g} pooled): "
      "p-value {:.3g} against {}\n{:>10} {:>12} {:>12} {:>12}\n",
      chi2, dof, observed.size(), kMinExpected, p_value, familyLine(*this), "cell", "observed",
      "expected", "contribution");
  std::sort(cells.begin(), cells.end(),
            [](const Cell& a, const Cell& b) { return a.contribution > b.contribution; });
  for (std::size_t i = 0; i < std::min(cells.size(), kCellsShown); ++i)
    table += fmt::format("{:>10} {:>12.6g} {:>12.6g} {:>12.4g}\n", cells[i].name, cells[i].observed,
                         cells[i].expected, cells[i].contribution);
  if (cells.size() > kCellsShown)
    table += fmt::format("({} more cells, contributing less)", cells.size() - kCellsShown);
  return verdict(p_value >= level(), table);
}

::testing::AssertionResult TestFamily::chiSquare(const DirectionSampler& sample,
                                                 const DirectionPdf& pdf) const {
  std::vector<double> expected = expectedProbabilities(pdf);
  const double total = std::accumulate(expected.begin(), expected.end(), 0.0);
  if (std::abs(total - 1.0) > 1e-3)
    return ::testing::AssertionFailure()
           << "the density integrates to " << total << " over the sphere, not to one";
  for (double& e : expected) e *= kChiSquareSamples;
  std::vector<double> observed(kCosThetaBins * kPhiBins, 0.0);
  for (int s = 0; s < kChiSquareSamples; ++s) {
    ref::SampleStream random(99, 0, std::uint32_t(s));
    observed[std::size_t(binOf(sample(random)))] += 1;
  }
  return chiSquare(observed, expected);
}

double TestFamily::criticalValue(double dof) const {
  const double p = 1 - level() / 2;
  return std::isinf(dof) ? metrics::normalQuantile(p) : metrics::studentTQuantile(p, dof);
}

::testing::AssertionResult TestFamily::tTest(double estimate, double expected,
                                             double standard_error, double dof,
                                             double allowance) const {
  // The deviation beyond the allowance; none at all passes whatever the standard error.
  const double excess = std::max(0.0, std::abs(estimate - expected) - allowance);
  const double statistic = excess > 0 ? excess / standard_error : 0.0;
  const bool normal = std::isinf(dof);
  const double p_value =
      2 * (normal ? metrics::normalCdf(-statistic) : metrics::studentTCdf(-statistic, dof));
  const std::string table = fmt::format(
      "{} test: p-value {:.3g} against {}\n"
      "{:>14} {:>14} {:>11} {:>14} {:>9} {:>10} {:>10}\n"
      "{:>14.8g} {:>14.8g} {:>11.4g} {:>14.4g} {:>9.6g} {:>10.4g} {:>10.4g}",
      normal ? "Z" : "Student's t", p_value, familyLine(*this), "estimate", "expected", "allowance",
      "standard error", "dof", "statistic", "bound", estimate, expected, allowance, standard_error,
      dof, statistic, criticalValue(dof));
  return verdict(p_value >= level(), table);
}

::testing::AssertionResult TestFamily::binomial(std::size_t count, std::size_t trials,
                                                double probability) const {
  // P(X ≥ k) = I_p(k, n − k + 1); P(X ≤ k) = 1 − P(X ≥ k + 1); twice the smaller tail, at most 1.
  auto at_least = [&](std::size_t k) {
    if (k == 0) return 1.0;
    if (k > trials) return 0.0;
    return metrics::regularizedBetaI(double(k), double(trials - k + 1), probability);
  };
  const double p_value = std::min(1.0, 2.0 * std::min(at_least(count), 1.0 - at_least(count + 1)));
  return verdict(p_value >= level(),
                 fmt::format("binomial test: {} of {} trials against the {:.4g} expected at "
                             "probability {:.4g}: p-value {:.3g} against {}",
                             count, trials, probability * double(trials), probability, p_value,
                             familyLine(*this)));
}

::testing::AssertionResult TestFamily::binomialAtMost(std::size_t count, std::size_t trials,
                                                      double probability) const {
  if (count > trials)
    return ::testing::AssertionFailure() << "binomial test of " << count << " events in only "
                                         << trials << " trials: count each trial once";
  // P(X ≥ k) = I_p(k, n − k + 1).
  const double p_value = count == 0 ? 1.0
                                    : metrics::regularizedBetaI(
                                          double(count), double(trials - count + 1), probability);
  return verdict(p_value >= level(),
                 fmt::format("one-sided binomial test: {} of {} trials against at most the {:.4g} "
                             "expected at probability {:.4g}: p-value {:.3g} against {}",
                             count, trials, probability * double(trials), probability, p_value,
                             familyLine(*this)));
}

}  // namespace gib::test
