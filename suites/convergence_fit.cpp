#include "suites/convergence_fit.h"

#include "metrics/convergence_fit.h"
#include "suites/primary_metric.h"

#include <cmath>
#include <string>
#include <vector>

namespace gib::suites {

void fitConvergence(results::Convergence& convergence) {
  if (convergence.points.empty()) return;
  const std::string metric = primaryMetric(convergence.points.front().metrics);
  std::vector<double> x, y;
  for (const results::Convergence::Point& point : convergence.points)
    for (const auto& [name, value] : point.metrics)
      if (name == metric && point.x > 0 && value > 0 && std::isfinite(value)) {
        x.push_back(std::log(point.x));
        y.push_back(std::log(value));
      }
  if (x.size() < 2) return;
  const metrics::LinearFit fit = metrics::fitLine(x, y);
  convergence.fit_metric = metric;
  convergence.fit_slope = fit.slope;
  convergence.fit_intercept = fit.intercept;
  convergence.fit_slope_ci95 = fit.slope_ci95;
}

}  // namespace gib::suites
