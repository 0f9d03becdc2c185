#include "metrics/timing_statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace gib::metrics {
namespace {

TEST(TimingStatistics, SummarisesASmallSample) {
  const std::vector<double> x = {5, 1, 4, 2, 3};
  TimingSummary s = summarizeTimings(x);
  EXPECT_EQ(s.count, 5u);
  EXPECT_EQ(s.median, 3);
  EXPECT_EQ(s.first_quartile, 2);
  EXPECT_EQ(s.third_quartile, 4);
  EXPECT_EQ(s.minimum, 1);
  EXPECT_EQ(s.maximum, 5);
  EXPECT_EQ(s.median_absolute_deviation, 1);  // |x − 3| = 2, 1, 0, 1, 2
}

TEST(TimingStatistics, QuantilesInterpolateBetweenOrderStatistics) {
  const std::vector<double> x = {10, 20, 30, 40};
  EXPECT_DOUBLE_EQ(quantile(x, 0.5), 25);
  EXPECT_DOUBLE_EQ(quantile(x, 0.25), 17.5);
  EXPECT_THROW(summarizeTimings(std::vector<double>{}), std::invalid_argument);
}

}  // namespace
}  // namespace gib::metrics

namespace gib::metrics {
namespace {

// Error rates of the timing tests under simulated noise: log-normal run-to-run noise (ln time
// normal, as the tests assume), a fixed seed, 20 000 trials. A false-positive rate is accepted
// when it lies under significance + 4 binomial standard deviations (a fair test fails this with
// probability 3e-5); a power when it is at least the stated 95% less 4 standard deviations.
constexpr int kTrials = 20000;
constexpr double kSignificance = 0.01;

double binomialBound(double rate) {
  return rate + 4.0 * std::sqrt(rate * (1 - rate) / kTrials);
}

struct NoiseSource {
  explicit NoiseSource(std::uint64_t seed) : generator(seed) {}
  double lognormal(double median, double sigma) {
    return median * std::exp(sigma * normal(generator));
  }
  std::mt19937_64 generator;
  std::normal_distribution<double> normal{0.0, 1.0};
};

TEST(TimingTests, TheRunToRunRuleFalselyRejectsAtItsSignificance) {
  NoiseSource noise(1);
  int rejected = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    std::vector<double> history;
    for (int i = 0; i < 8; ++i) history.push_back(noise.lognormal(10, 0.08));
    const double base = noise.lognormal(10, 0.08), next = noise.lognormal(10, 0.08);
    rejected +=
        testAgainstRunToRunSpread(base, next, history, kSignificance).p_value < kSignificance;
  }
  EXPECT_LT(double(rejected) / kTrials, binomialBound(kSignificance)) << rejected;
  EXPECT_GT(rejected, 0);  // the test is not simply blind
}

TEST(TimingTests, TheRunToRunRuleDetectsItsStatedDetectableChange) {
  NoiseSource noise(2);
  std::vector<double> history;
  for (int i = 0; i < 10; ++i) history.push_back(noise.lognormal(10, 0.05));
  const double detectable =
      testAgainstRunToRunSpread(10, 10, history, kSignificance).detectable_change;
  // Runs drawn around base and around base·(1 + detectable): detected at about 95%.
  int detected = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    const double base = noise.lognormal(10, 0.05);
    const double next = noise.lognormal(10 * (1 + detectable), 0.05);
    detected +=
        testAgainstRunToRunSpread(base, next, history, kSignificance).p_value < kSignificance;
  }
  // The stated power holds for the noise the history estimated; this history's estimate is near
  // the truth, so the rate is near 95% (within the estimate's own error of some percent).
  EXPECT_GT(double(detected) / kTrials, 0.85) << detected;
}

// Interleaved A/B pairs: the machine drifts by 30% between pairs, far more than the pairs' own
// 5% noise, and one run in ten lands in another scheduling mode (a third slower or faster: more
// often than the one in twenty-five measured on llvmpipe); with the recommended pairs, the
// signed-rank test must neither flag that nor miss a 25% slowdown under it.
TEST(TimingTests, InterleavedPairsIgnoreDriftAndOutliersAndCatchASlowdown) {
  NoiseSource noise(3);
  std::bernoulli_distribution outlier(0.1);
  std::uniform_real_distribution<double> mode(0.67, 1.5);
  auto run = [&](double median) {
    const double t = noise.lognormal(median, 0.05);
    return outlier(noise.generator) ? t * mode(noise.generator) : t;
  };
  const int pairs = recommendedPairs(kSignificance);
  int false_alarms = 0, detected = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    std::vector<double> a, b, slow;
    for (int i = 0; i < pairs; ++i) {
      const double machine = noise.lognormal(10, 0.3);
      a.push_back(run(machine));
      b.push_back(run(machine));
      slow.push_back(run(1.25 * machine));
    }
    false_alarms += testInterleavedPairs(a, b, kSignificance).p_value < kSignificance;
    detected += testInterleavedPairs(a, slow, kSignificance).p_value < kSignificance;
  }
  EXPECT_LT(double(false_alarms) / kTrials, binomialBound(kSignificance)) << false_alarms;
  EXPECT_GT(double(detected) / kTrials, 0.95) << detected;
}

TEST(TimingTests, SignedRankPValuesAreExact) {
  // Every difference positive: only one of the 2ⁿ sign patterns is as extreme, on each side.
  EXPECT_NEAR(wilcoxonSignedRankP(std::vector<double>{1, 2, 3, 4, 5}), 2.0 / 32, 1e-15);
  EXPECT_NEAR(wilcoxonSignedRankP(std::vector<double>{1, 2, 3, 4, 5, 6}), 2.0 / 64, 1e-15);
  // The smallest one negative: W⁺ = 20 of 21; P(W⁺ ≥ 20) = 2/64.
  EXPECT_NEAR(wilcoxonSignedRankP(std::vector<double>{-1, 2, 3, 4, 5, 6}), 4.0 / 64, 1e-15);
  EXPECT_EQ(wilcoxonSignedRankP(std::vector<double>{0, 0}), 1.0);
  EXPECT_NEAR(wilcoxonSignedRankP(std::vector<double>{1, -1}), 1.0, 1e-15);
  EXPECT_EQ(pairsFor(0.01), 9);  // 2⁹ = 512 ≥ 400
  // Sixteen pairs: the largest and the smallest difference reversed still give p ≤ 0.01
  // (W⁻ = 17: p = 0.0063), which fifteen do not (W⁻ = 16: p = 0.0103).
  EXPECT_EQ(recommendedPairs(0.01), 16);
  std::vector<double> hiccup;
  for (int rank = 1; rank <= 16; ++rank) hiccup.push_back(rank == 1 || rank == 16 ? -rank : rank);
  EXPECT_LE(wilcoxonSignedRankP(hiccup), 0.01);
  hiccup.pop_back();
  hiccup.back() = -15;
  EXPECT_GT(wilcoxonSignedRankP(hiccup), 0.01);
  // Fewer pairs than the significance allows detect nothing, and say so.
  EXPECT_TRUE(std::isinf(testInterleavedPairs(std::vector<double>{1, 2, 3},
                                              std::vector<double>{2, 3, 4}, kSignificance)
                             .detectable_change));
}

// Frames of two runs see only their own noise: with a drift between the runs they reject far
// more often than their significance, which is why the diff never takes them as proof.
TEST(TimingTests, FramesAloneMistakeDriftForAChange) {
  NoiseSource noise(4);
  int rejected = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<double> a, b;
    const double run_a = noise.lognormal(10, 0.1), run_b = noise.lognormal(10, 0.1);
    for (int i = 0; i < 16; ++i) {
      a.push_back(noise.lognormal(run_a, 0.02));
      b.push_back(noise.lognormal(run_b, 0.02));
    }
    rejected += testWithinRuns(a, b, kSignificance).p_value < kSignificance;
  }
  EXPECT_GT(rejected, 2000 / 2);  // most of them, at a nominal 1%
}

TEST(TimingTests, RefuseTooFewSamplesAndBadTimes) {
  const std::vector<double> one = {1.0}, two = {1.0, 2.0}, bad = {1.0, -2.0};
  EXPECT_THROW(testAgainstRunToRunSpread(1, 2, one, kSignificance), std::invalid_argument);
  EXPECT_THROW(testInterleavedPairs(one, one, kSignificance), std::invalid_argument);
  EXPECT_THROW(testInterleavedPairs(two, one, kSignificance), std::invalid_argument);
  EXPECT_THROW(testWithinRuns(two, bad, kSignificance), std::invalid_argument);
  EXPECT_NEAR(runToRunSpread(std::vector<double>{10, 10, 10}), 0.0, 1e-15);
}

}  // namespace
}  // namespace gib::metrics
