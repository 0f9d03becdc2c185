// Robust summaries of timing samples and a test of whether two samples differ: these machines
// are shared and noisy, so medians and rank tests rather than means and t-tests.
#pragma once

#include <cstddef>
#include <span>

namespace gib::metrics {

struct TimingSummary {
  std::size_t count = 0;
  double median = 0;
  double first_quartile = 0;  // quantiles by linear interpolation between order statistics
  double third_quartile = 0;
  double minimum = 0;
  double maximum = 0;
  double median_absolute_deviation = 0;  // median |x − median|, unscaled
  bool operator==(const TimingSummary&) const = default;
};

// Throws std::invalid_argument for an empty sample.
TimingSummary summarizeTimings(std::span<const double> samples);

// The q-quantile (0 ≤ q ≤ 1) by linear interpolation between order statistics (Hyndman & Fan
// type 7, the default of R and NumPy).
double quantile(std::span<const double> samples, double q);

struct MannWhitneyResult {
  double u = 0;        // U statistic of the first sample
  double z = 0;        // normal approximation with tie and continuity corrections
  double p_value = 1;  // two-sided
};

// Mann–Whitney U test: do the two samples come from the same distribution? The normal
// approximation is accurate for samples of about eight or more each. Throws for an empty sample.
MannWhitneyResult mannWhitneyU(std::span<const double> a, std::span<const double> b);

}  // namespace gib::metrics
