// The convergence of a job's error as a power law: the least-squares line through log(error)
// against log(spp or iterations), whose slope the report shows beside the plot (−1 for an
// unbiased Monte Carlo estimator's relMSE against samples).
#pragma once

#include "results/results.h"

namespace gib::suites {

// Fits the points of `convergence` in the metric suites/primary_metric.h picks from its first
// point, over the points of positive x and a positive, finite value; sets fit_metric,
// fit_slope, fit_intercept and fit_slope_ci95. Leaves them unset (fit_metric empty) with fewer
// than two such points.
void fitConvergence(results::Convergence& convergence);

}  // namespace gib::suites
