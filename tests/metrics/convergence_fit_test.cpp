#include "metrics/convergence_fit.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace gib::metrics {
namespace {

TEST(ConvergenceFit, RecoversAnExactLine) {
  std::vector<double> x = {0, 1, 2, 3, 4}, y;
  for (double v : x) y.push_back(2.5 - 0.5 * v);
  LinearFit fit = fitLine(x, y);
  EXPECT_NEAR(fit.slope, -0.5, 1e-12);
  EXPECT_NEAR(fit.intercept, 2.5, 1e-12);
  EXPECT_NEAR(fit.slope_ci95, 0.0, 1e-9);
}

TEST(ConvergenceFit, ConfidenceIntervalCoversTheTrueSlopeOfNoisyData) {
  // Residuals ±0.1 alternating: the interval is wide enough to contain the true slope.
  std::vector<double> x = {0, 1, 2, 3, 4, 5, 6, 7}, y;
  for (std::size_t i = 0; i < x.size(); ++i) y.push_back(1.0 - 0.5 * x[i] + (i % 2 ? 0.1 : -0.1));
  LinearFit fit = fitLine(x, y);
  EXPECT_GT(fit.slope_ci95, 0);
  EXPECT_LE(std::abs(fit.slope + 0.5), fit.slope_ci95);
}

TEST(ConvergenceFit, RejectsDegenerateInput) {
  std::vector<double> one = {1};
  EXPECT_THROW(fitLine(one, one), std::invalid_argument);
  std::vector<double> same = {2, 2, 2}, y = {1, 2, 3};
  EXPECT_THROW(fitLine(same, y), std::invalid_argument);
}

}  // namespace
}  // namespace gib::metrics
