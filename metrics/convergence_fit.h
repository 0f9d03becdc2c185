// Least-squares line fit, for convergence plots: log error against log samples (or log seconds).
#pragma once

#include <span>

namespace gib::metrics {

struct LinearFit {
  double slope = 0;
  double intercept = 0;
  double slope_standard_error = 0;
  // Half-width of the 95% confidence interval of the slope (Student t with n − 2 degrees of
  // freedom); infinite with fewer than three points.
  double slope_ci95 = 0;
};

// Throws std::invalid_argument for fewer than two points, unequal lengths or constant x.
LinearFit fitLine(std::span<const double> x, std::span<const double> y);

}  // namespace gib::metrics
