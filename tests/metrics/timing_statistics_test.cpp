#include "metrics/timing_statistics.h"

#include <gtest/gtest.h>

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

TEST(MannWhitney, MatchesTheNormalApproximationOfATextbookCase) {
  // Completely separated samples of five: U = 0, z = (12.5 − 0.5)/sqrt(25·11/12) = 2.5067,
  // two-sided p = 0.01219 (R: wilcox.test(a, b, exact = FALSE, correct = TRUE)).
  const std::vector<double> a = {1, 2, 3, 4, 5}, b = {6, 7, 8, 9, 10};
  MannWhitneyResult r = mannWhitneyU(a, b);
  EXPECT_EQ(r.u, 0);
  EXPECT_NEAR(r.p_value, 0.01219, 1e-4);
}

TEST(MannWhitney, SeesAShiftButNotReordering) {
  std::vector<double> a, b, shuffled;
  for (int i = 0; i < 20; ++i) {
    a.push_back(10 + (i * 7) % 20 * 0.1);
    b.push_back(10.5 + (i * 3) % 20 * 0.1);
  }
  EXPECT_LT(mannWhitneyU(a, b).p_value, 0.05);
  shuffled.assign(a.rbegin(), a.rend());
  EXPECT_GT(mannWhitneyU(a, shuffled).p_value, 0.9);
  // All values tied: no evidence either way.
  const std::vector<double> same = {1, 1, 1};
  EXPECT_EQ(mannWhitneyU(same, same).p_value, 1.0);
}

}  // namespace
}  // namespace gib::metrics
