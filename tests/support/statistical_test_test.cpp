// The statistical-test helper itself: Šidák's level and the family-wise rate it keeps, and each
// test against known p-values, accepting a right distribution or mean and rejecting a wrong one.
#include "support/statistical_test.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace gib::test {
namespace {

using ::testing::HasSubstr;

// The checks below that a correct helper can fail by chance: the simulated family-wise rate, and
// the right die and the right mean accepted. Every other check is exact.
constexpr TestFamily kFamily(0.01, 3);

double gaussian(ref::SampleStream& random) {
  const double u1 = 1.0 - random.next(), u2 = random.next();
  return std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
}

TEST(StatisticalTest, EachTestRunsAtSidaksLevel) {
  const TestFamily family(0.01, 100);
  EXPECT_NEAR(family.level(), 1 - std::pow(0.99, 0.01), 1e-15);
  EXPECT_NEAR(1 - std::pow(1 - family.level(), 100), 0.01, 1e-12);
  EXPECT_NEAR(TestFamily(0.05, 1).level(), 0.05, 1e-15);
  // Two-sided critical values of the usual tables at 5%: the normal's and t₁₀'s.
  EXPECT_NEAR(TestFamily(0.05, 1).criticalValue(), 1.959964, 1e-6);
  EXPECT_NEAR(TestFamily(0.05, 1).criticalValue(10), 2.2281, 1e-4);
  EXPECT_THROW(TestFamily(0.0, 1), std::invalid_argument);
  EXPECT_THROW(TestFamily(1.0, 1), std::invalid_argument);
  EXPECT_THROW(TestFamily(0.01, 0), std::invalid_argument);
}

// 4000 families of ten Z tests on standard normal draws, each family at α = 0.1: about 400 fail
// (one or more of their tests rejects), as many as Binomial(4000, 0.1) allows. Without the
// correction (each test at 0.1) about 2600 would, which the same binomial test rejects.
TEST(StatisticalTest, AFamilyOfCorrectTestsFailsAtItsSignificance) {
  constexpr int kFamilies = 4000, kTests = 10;
  const TestFamily family(0.1, kTests), uncorrected(0.1, 1);
  std::size_t failed = 0, failed_uncorrected = 0;
  for (int f = 0; f < kFamilies; ++f) {
    bool passed = true, passed_uncorrected = true;
    for (int t = 0; t < kTests; ++t) {
      ref::SampleStream random(42, std::uint32_t(f), std::uint32_t(t));
      const double z = gaussian(random);
      passed = family.zTest(z, 0.0, 1.0) && passed;
      passed_uncorrected = uncorrected.zTest(z, 0.0, 1.0) && passed_uncorrected;
    }
    failed += !passed;
    failed_uncorrected += !passed_uncorrected;
  }
  EXPECT_TRUE(kFamily.binomial(failed, kFamilies, 0.1));
  EXPECT_FALSE(kFamily.binomial(failed_uncorrected, kFamilies, 0.1));
}

TEST(StatisticalTest, ChiSquareHasTheKnownPValueAndPoolsSparseCells) {
  // (60 − 50)²/50 + (40 − 50)²/50 = 4 over one degree of freedom: p = 0.0455.
  EXPECT_FALSE(TestFamily(0.05, 1).chiSquare({60, 40}, {50, 50}));
  EXPECT_TRUE(TestFamily(0.04, 1).chiSquare({60, 40}, {50, 50}));
  // Eight cells expected at 1 each hold 8 counts together, all in one: pooled they match; apart
  // they would contribute 56 to the statistic.
  const std::vector<double> observed = {50, 50, 0, 0, 0, 0, 0, 0, 0, 8};
  const std::vector<double> expected = {50, 50, 1, 1, 1, 1, 1, 1, 1, 1};
  EXPECT_TRUE(kFamily.chiSquare(observed, expected));
  // Fewer than two cells to compare, or counts that do not pair up, are errors.
  EXPECT_THAT(std::string(kFamily.chiSquare({3, 1}, {2, 2}).message()),
              HasSubstr("give the test more samples"));
  EXPECT_FALSE(kFamily.chiSquare({1, 2, 3}, {2, 4}));
}

// 20 000 draws of a loaded die (face k with probability k/21) match their own distribution and
// not a fair die's; the failure's table names the cells.
TEST(StatisticalTest, ChiSquareAcceptsTheRightDistributionAndRejectsAWrongOne) {
  constexpr int kDraws = 20000;
  std::vector<double> observed(6, 0.0), loaded(6), fair(6, kDraws / 6.0);
  for (int k = 0; k < 6; ++k) loaded[std::size_t(k)] = kDraws * (k + 1) / 21.0;
  for (std::uint32_t i = 0; i < kDraws; ++i) {
    double u = ref::SampleStream(7, i, 0).next() * 21;
    int face = 0;
    while (face < 5 && u >= face + 1) u -= ++face;
    observed[std::size_t(face)] += 1;
  }
  EXPECT_TRUE(kFamily.chiSquare(observed, loaded));
  const ::testing::AssertionResult against_fair = kFamily.chiSquare(observed, fair);
  EXPECT_FALSE(against_fair);
  EXPECT_THAT(std::string(against_fair.message()),
              AllOf(HasSubstr("observed"), HasSubstr("expected"), HasSubstr("contribution"),
                    HasSubstr("p-value"), HasSubstr("level")));
}

TEST(StatisticalTest, ChiSquareOfDirectionsNeedsADensityOfIntegralOne) {
  const DirectionPdf half = [](const glm::vec3&) { return 0.5 / (4 * std::numbers::pi); };
  const DirectionSampler pole = [](ref::SampleStream&) { return glm::vec3(0, 0, 1); };
  EXPECT_THAT(std::string(kFamily.chiSquare(pole, half).message()), HasSubstr("integrates to 0.5"));
}

// The mean of 30 normal draws of mean 1 and standard deviation 1, with its standard error from
// their spread (29 degrees of freedom), against the right mean and a wrong one.
TEST(StatisticalTest, StudentsTAcceptsTheRightMeanAndRejectsAWrongOne) {
  constexpr int kDraws = 30;
  double sum = 0, squares = 0;
  for (std::uint32_t i = 0; i < kDraws; ++i) {
    ref::SampleStream random(3, i, 0);
    const double x = 1.0 + gaussian(random);
    sum += x;
    squares += x * x;
  }
  const double mean = sum / kDraws;
  const double standard_error = std::sqrt((squares - kDraws * mean * mean) / (kDraws - 1) / kDraws);
  EXPECT_TRUE(kFamily.tTest(mean, 1.0, standard_error, kDraws - 1));
  const ::testing::AssertionResult wrong = kFamily.tTest(mean, 2.0, standard_error, kDraws - 1);
  EXPECT_FALSE(wrong);
  EXPECT_THAT(std::string(wrong.message()),
              AllOf(HasSubstr("Student's t"), HasSubstr("estimate"), HasSubstr("standard error"),
                    HasSubstr("statistic"), HasSubstr("p-value"), HasSubstr("level")));
}

// The test passes exactly within allowance + k standard errors, k its critical value.
TEST(StatisticalTest, TheBoundIsTheCriticalValueBeyondTheAllowance) {
  const TestFamily family(0.01, 6);
  for (double dof : {kKnownStandardError, 7.0}) {
    const double k = family.criticalValue(dof);
    EXPECT_TRUE(family.tTest(1.0 + 0.1 + 0.999 * k * 0.02, 1.0, 0.02, dof, 0.1)) << dof;
    EXPECT_FALSE(family.tTest(1.0 + 0.1 + 1.001 * k * 0.02, 1.0, 0.02, dof, 0.1)) << dof;
    EXPECT_FALSE(family.tTest(1.0 - 0.1 - 1.001 * k * 0.02, 1.0, 0.02, dof, 0.1)) << dof;
  }
  // Z's bound at 5% two-sided: 1.96 standard errors.
  EXPECT_TRUE(TestFamily(0.05, 1).zTest(1.95, 0, 1));
  EXPECT_FALSE(TestFamily(0.05, 1).zTest(1.97, 0, 1));
  // A noise-free estimate passes within its allowance and fails beyond it.
  EXPECT_TRUE(kFamily.zTest(1.0 + 1e-7, 1.0, 0.0, 1e-6));
  EXPECT_FALSE(kFamily.zTest(1.0 + 1e-5, 1.0, 0.0, 1e-6));
}

TEST(StatisticalTest, BinomialTestsHaveTheKnownPValues) {
  // Binomial(10, 0.5): P(X ≥ 9) = 11/1024 = 0.0107, so 9 of 10 has two-sided p 0.0215.
  EXPECT_FALSE(TestFamily(0.05, 1).binomial(9, 10, 0.5));
  EXPECT_TRUE(TestFamily(0.02, 1).binomial(9, 10, 0.5));
  EXPECT_FALSE(TestFamily(0.02, 1).binomialAtMost(9, 10, 0.5));
  EXPECT_TRUE(TestFamily(0.01, 1).binomialAtMost(9, 10, 0.5));
  // Too few events fail the two-sided test only.
  EXPECT_FALSE(TestFamily(0.05, 1).binomial(1, 10, 0.5));
  EXPECT_TRUE(TestFamily(0.05, 1).binomialAtMost(1, 10, 0.5));
  EXPECT_TRUE(TestFamily(0.05, 1).binomialAtMost(0, 10, 0.5));
  EXPECT_FALSE(kFamily.binomialAtMost(11, 10, 0.5));
}

}  // namespace
}  // namespace gib::test
