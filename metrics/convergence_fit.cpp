#include "metrics/convergence_fit.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace gib::metrics {

namespace {

// Two-sided 97.5% quantile of Student's t for small degrees of freedom; the normal value beyond.
double studentT975(std::size_t dof) {
  static const double kTable[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306,
                                  2.262,  2.228, 2.201, 2.179, 2.160, 2.145, 2.131, 2.120,
                                  2.110,  2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064,
                                  2.060,  2.056, 2.052, 2.048, 2.045, 2.042};
  if (dof == 0) return std::numeric_limits<double>::infinity();
  if (dof <= 30) return kTable[dof - 1];
  return 1.960 + 2.4 / double(dof);  // within 0.002 of the exact value for dof > 30
}

}  // namespace

LinearFit fitLine(std::span<const double> x, std::span<const double> y) {
  if (x.size() != y.size() || x.size() < 2)
    throw std::invalid_argument("fitLine needs two or more (x, y) pairs");
  const double n = double(x.size());
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= n;
  my /= n;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  if (sxx <= 0) throw std::invalid_argument("fitLine needs at least two distinct x values");
  LinearFit fit;
  fit.slope = sxy / sxx;
  fit.intercept = my - fit.slope * mx;
  if (x.size() > 2) {
    double residual = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      double r = y[i] - (fit.intercept + fit.slope * x[i]);
      residual += r * r;
    }
    fit.slope_standard_error = std::sqrt(residual / (n - 2) / sxx);
    fit.slope_ci95 = studentT975(x.size() - 2) * fit.slope_standard_error;
  } else {
    fit.slope_ci95 = std::numeric_limits<double>::infinity();
  }
  return fit;
}

}  // namespace gib::metrics
