#include "metrics/timing_statistics.h"

#include "metrics/distributions.h"
#include "support/statistical_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <utility>
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
// normal, as the tests assume), a fixed seed, 20 000 trials. A false-positive rate is tested
// against the significance (one-sided: a rate below it is no fault), a power against the stated
// 95%.
constexpr int kTrials = 20000;
constexpr double kSignificance = 0.01;  // the timing tests' own, which the simulations measure

// Correct timing tests fail one of this file's six rate tests (the run-to-run rule's and the
// interleaved pairs' false-positive rates, the power at the stated change of the run-to-run rule,
// of the tests within runs on repeats and on frames, and of the interleaved pairs) with
// probability 1%.
constexpr test::TestFamily kFamily(0.01, 6);

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
  EXPECT_TRUE(kFamily.binomialAtMost(std::size_t(rejected), kTrials, kSignificance));
  EXPECT_GT(rejected, 0);  // the test is not simply blind
}

// The smallest change each test states it detects ("detects changes of X% or more", and the gate
// of results::worthConfirming), checked from both sides by simulation: with the new samples
// scaled by 1 + X the test rejects "no change" 95% of the time, and well less often at 1 + X/2 (a
// stated change twice too large would still be detected 95% of the time there). X depends only
// on the samples' spread, which scaling the new ones leaves as it is, so each trial states its X
// before the shift and is tested after it.
constexpr int kPowerTrials = 4000;
// The standard error of a rejection rate over kPowerTrials where the power is the stated 95%.
const double kPowerStandardError =
    std::sqrt(kDetectionPower * (1 - kDetectionPower) / kPowerTrials);
// At half the stated change the tests reject 12-48% of the time (20 000 trials each: 3 + 3 and
// 16 + 16 samples, 10 history runs, 16 pairs); 60% leaves room for the trials' noise.
constexpr double kPowerAtHalfTheChange = 0.6;

struct StatedChangePower {
  double at_stated = 0, at_half = 0;  // rejection rates
};

std::vector<double> scaled(std::vector<double> samples, double factor) {
  for (double& x : samples) x *= factor;
  return samples;
}

// `draw(noise)` makes one trial: a function from the factor its new samples are scaled by to the
// test of them.
template <class Draw>
StatedChangePower powerAtTheStatedChange(NoiseSource& noise, const Draw& draw) {
  int at_stated = 0, at_half = 0;
  for (int trial = 0; trial < kPowerTrials; ++trial) {
    const auto test = draw(noise);
    const double stated = test(1.0).detectable_change;
    at_stated += test(1 + stated).p_value < kSignificance;
    at_half += test(1 + stated / 2).p_value < kSignificance;
  }
  return {double(at_stated) / kPowerTrials, double(at_half) / kPowerTrials};
}

// `allowance`: how far the test's own approximation may put its power from 95%, beyond the
// trials' noise.
void expectStatedPower(const StatedChangePower& power, double allowance) {
  EXPECT_TRUE(kFamily.zTest(power.at_stated, kDetectionPower, kPowerStandardError, allowance));
  EXPECT_LT(power.at_half, kPowerAtHalfTheChange);
}

TEST(TimingTests, TheRunToRunRuleDetectsItsStatedChangeAndNotHalfOfIt) {
  NoiseSource noise(2);
  const StatedChangePower power = powerAtTheStatedChange(noise, [](NoiseSource& n) {
    std::vector<double> history;
    for (int i = 0; i < 10; ++i) history.push_back(n.lognormal(10, 0.05));
    const double base = n.lognormal(10, 0.05), next = n.lognormal(10, 0.05);
    return [=](double factor) {
      return testAgainstRunToRunSpread(base, next * factor, history, kSignificance);
    };
  });
  // Exact: at the stated shift (t₀.₉₉₅ + t₀.₉₅)·s·√2 the statistic is t₀.₉₉₅ + t₀.₉₅ plus a Student
  // t variable of k − 1 degrees of freedom, which exceeds −t₀.₉₅ 95% of the time.
  expectStatedPower(power, 0.0);
}

TEST(TimingTests, WithinRunsDetectTheirStatedChangeAndNotHalfOfIt) {
  for (const int samples : {3, 16}) {  // repeats of each run; frames of each run
    NoiseSource noise{std::uint64_t(samples)};
    const StatedChangePower power = powerAtTheStatedChange(noise, [samples](NoiseSource& n) {
      std::vector<double> a, b;
      for (int i = 0; i < samples; ++i) {
        a.push_back(n.lognormal(10, 0.05));
        b.push_back(n.lognormal(10, 0.05));
      }
      return [a, b](double factor) { return testWithinRuns(a, scaled(b, factor), kSignificance); };
    });
    // Welch–Satterthwaite's degrees of freedom are an approximation: with 3 + 3 samples the power
    // at the stated change is 96.0% (20 000 trials), hence 1% allowed.
    SCOPED_TRACE(samples);
    expectStatedPower(power, 0.01);
  }
}

// The pairs drift by 30% from pair to pair, as a shared machine does, which the pairing cancels.
TEST(TimingTests, InterleavedPairsDetectTheirStatedChangeAndNotHalfOfIt) {
  NoiseSource noise(6);
  const int pairs = recommendedPairs(kSignificance);
  const StatedChangePower power = powerAtTheStatedChange(noise, [pairs](NoiseSource& n) {
    std::vector<double> a, b;
    for (int i = 0; i < pairs; ++i) {
      const double machine = n.lognormal(10, 0.3);
      a.push_back(n.lognormal(machine, 0.05));
      b.push_back(n.lognormal(machine, 0.05));
    }
    return
        [a, b](double factor) { return testInterleavedPairs(a, scaled(b, factor), kSignificance); };
  });
  // The stated change is itself found by simulation (its power within ±0.3% at two standard
  // errors), hence 0.5% allowed.
  expectStatedPower(power, 0.005);
}

// Welch's test of the logs written out from its definition: the p-value and the stated change
// that a verdict on repeats or frames prints.
TEST(TimingTests, WithinRunsFollowWelchsTestOfTheLogs) {
  const std::vector<double> a = {9.8, 10.4, 10.1, 9.6}, b = {10.9, 11.6, 10.7};
  auto meanAndVarianceOfLogs = [](const std::vector<double>& x) {
    double sum = 0, squares = 0;
    for (double v : x) sum += std::log(v);
    const double mean = sum / double(x.size());
    for (double v : x) squares += (std::log(v) - mean) * (std::log(v) - mean);
    return std::pair{mean, squares / double(x.size() - 1)};
  };
  const auto [mean_a, variance_a] = meanAndVarianceOfLogs(a);
  const auto [mean_b, variance_b] = meanAndVarianceOfLogs(b);
  const double va = variance_a / 4, vb = variance_b / 3;
  const double se = std::sqrt(va + vb);
  const double dof = (va + vb) * (va + vb) / (va * va / 3 + vb * vb / 2);
  const TimingTest test = testWithinRuns(a, b, kSignificance);
  EXPECT_NEAR(test.ratio, std::exp(mean_b - mean_a), 1e-12);
  EXPECT_NEAR(test.degrees_of_freedom, dof, 1e-9);
  EXPECT_NEAR(test.p_value, 2 * (1 - studentTCdf(std::abs(mean_b - mean_a) / se, dof)), 1e-9);
  EXPECT_NEAR(test.detectable_change,
              std::exp((studentTQuantile(1 - kSignificance / 2, dof) +
                        studentTQuantile(kDetectionPower, dof)) *
                       se) -
                  1,
              1e-9);
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
  EXPECT_TRUE(kFamily.binomialAtMost(std::size_t(false_alarms), kTrials, kSignificance));
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
