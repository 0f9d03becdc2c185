// The statistical tests of the test suite, in the manner of Mitsuba's ChiSquareTest. A test file
// states its family once: the significance α at which a correct implementation may fail any of
// its tests, and the number n of such tests it runs. Each test then runs at Šidák's per-test
// level 1 − (1 − α)^(1/n), so that a correct implementation passes all n together with
// probability 1 − α, and no test picks its own bound ("3 standard errors").
//
// Every test returns a GoogleTest AssertionResult whose message is its table (the chi-square
// test: statistic, degrees of freedom, p-value and level, and the cells that contribute most,
// observed, expected and contribution; the others: estimate, expected, allowance, standard error,
// degrees of freedom, statistic, p-value and level). EXPECT_TRUE prints it when a test fails;
// EXPECT_FALSE prints it when a test that must reject (a check of the test's power, which is not
// one of the n) does not.
#pragma once

#include "reference/rng.h"

#include <gtest/gtest.h>
#include <glm/vec3.hpp>

#include <cstddef>
#include <functional>
#include <limits>
#include <stdexcept>
#include <vector>

namespace gib::test {

using DirectionSampler = std::function<glm::vec3(ref::SampleStream&)>;
using DirectionPdf = std::function<double(const glm::vec3&)>;

// The degrees of freedom of a standard error that is known rather than estimated: its statistic
// is normal (a Z test).
inline constexpr double kKnownStandardError = std::numeric_limits<double>::infinity();

class TestFamily {
 public:
  // `significance`: α in (0, 1); `tests`: n ≥ 1, the tests of the family a correct
  // implementation must pass. Both are checked when the family is made, at compile time for a
  // constexpr one.
  constexpr TestFamily(double significance, int tests)
      : significance_(significance), tests_(tests) {
    if (!(significance > 0 && significance < 1))
      throw std::invalid_argument("a test family's significance must lie in (0, 1)");
    if (tests < 1) throw std::invalid_argument("a test family holds one test or more");
  }

  double significance() const { return significance_; }
  int tests() const { return tests_; }
  // Šidák's per-test level, 1 − (1 − α)^(1/n): a test passes when its p-value is at least this.
  double level() const;

  // Chi-square goodness of fit of counts against expected counts of the same total over discrete
  // cells; the cells expected below 5 (where the statistic's distribution is not chi-square) are
  // pooled into one.
  ::testing::AssertionResult chiSquare(const std::vector<double>& observed,
                                       const std::vector<double>& expected) const;

  // pbrt-v4's test of a direction sampler against its density: 10⁶ directions (fixed streams)
  // binned on the sphere in (cos θ, φ) against the density integrated over each bin. A density that
  // does not integrate to one (within 1e-3) fails it.
  ::testing::AssertionResult chiSquare(const DirectionSampler& sample,
                                       const DirectionPdf& pdf) const;

  // Two-sided test of an estimate against its expected value: the statistic is how far the
  // estimate lies beyond `allowance` (a known deterministic error, such as float rounding or a
  // discretisation, which noise is not asked to explain), over its standard error. It follows
  // Student's t with `dof` degrees of freedom, the normal where the standard error is known
  // (kKnownStandardError). Passes when |estimate − expected| ≤ allowance + k · standard_error,
  // k = criticalValue(dof): the "within k standard errors" bound, with k from the family.
  ::testing::AssertionResult tTest(double estimate, double expected, double standard_error,
                                   double dof, double allowance = 0) const;
  ::testing::AssertionResult zTest(double estimate, double expected, double standard_error,
                                   double allowance = 0) const {
    return tTest(estimate, expected, standard_error, kKnownStandardError, allowance);
  }
  // k: the two-sided quantile of the t (or normal) statistic at the family's per-test level.
  double criticalValue(double dof = kKnownStandardError) const;

  // Exact binomial tests of `count` events in `trials` independent trials of probability
  // `probability` each: two-sided (as many as the probability gives), and one-sided (no more
  // than it gives: a false-alarm rate that may be lower than its bound, never higher).
  ::testing::AssertionResult binomial(std::size_t count, std::size_t trials,
                                      double probability) const;
  ::testing::AssertionResult binomialAtMost(std::size_t count, std::size_t trials,
                                            double probability) const;

 private:
  double significance_;
  int tests_;
};

}  // namespace gib::test
