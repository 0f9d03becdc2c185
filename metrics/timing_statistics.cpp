#include "metrics/timing_statistics.h"

#include "metrics/distributions.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace gib::metrics {

double quantile(std::span<const double> samples, double q) {
  if (samples.empty()) throw std::invalid_argument("quantile of an empty sample");
  std::vector<double> sorted(samples.begin(), samples.end());
  std::sort(sorted.begin(), sorted.end());
  const double position = q * double(sorted.size() - 1);
  const auto below = std::size_t(std::floor(position));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  const double fraction = position - double(below);
  return sorted[below] + fraction * (sorted[above] - sorted[below]);
}

TimingSummary summarizeTimings(std::span<const double> samples) {
  if (samples.empty()) throw std::invalid_argument("no timing samples to summarise");
  TimingSummary s;
  s.count = samples.size();
  s.median = quantile(samples, 0.5);
  s.first_quartile = quantile(samples, 0.25);
  s.third_quartile = quantile(samples, 0.75);
  s.minimum = *std::min_element(samples.begin(), samples.end());
  s.maximum = *std::max_element(samples.begin(), samples.end());
  std::vector<double> deviations;
  for (double x : samples) deviations.push_back(std::abs(x - s.median));
  s.median_absolute_deviation = quantile(deviations, 0.5);
  return s;
}

MannWhitneyResult mannWhitneyU(std::span<const double> a, std::span<const double> b) {
  if (a.empty() || b.empty()) throw std::invalid_argument("Mann-Whitney needs two samples");
  // Rank the pooled sample, giving tied values their average rank.
  struct Value {
    double x;
    bool first;
  };
  std::vector<Value> pooled;
  for (double x : a) pooled.push_back({x, true});
  for (double x : b) pooled.push_back({x, false});
  std::sort(pooled.begin(), pooled.end(), [](const Value& l, const Value& r) { return l.x < r.x; });
  const double n1 = double(a.size()), n2 = double(b.size()), n = n1 + n2;
  double rank_sum_first = 0, tie_term = 0;
  for (std::size_t i = 0; i < pooled.size();) {
    std::size_t j = i;
    while (j < pooled.size() && pooled[j].x == pooled[i].x) ++j;
    const double ties = double(j - i);
    const double average_rank = (double(i + 1) + double(j)) / 2.0;
    for (std::size_t k = i; k < j; ++k)
      if (pooled[k].first) rank_sum_first += average_rank;
    tie_term += ties * ties * ties - ties;
    i = j;
  }
  MannWhitneyResult r;
  r.u = rank_sum_first - n1 * (n1 + 1) / 2.0;
  const double mean_u = n1 * n2 / 2.0;
  const double variance_u = n1 * n2 / 12.0 * ((n + 1) - tie_term / (n * (n - 1)));
  if (variance_u <= 0) return r;  // every value tied: no evidence of a difference
  // Continuity correction: U moves in steps of 1 (or 1/2 with ties).
  const double distance = std::max(0.0, std::abs(r.u - mean_u) - 0.5);
  r.z = (r.u > mean_u ? 1 : -1) * distance / std::sqrt(variance_u);
  r.p_value = std::min(1.0, 2.0 * (1.0 - normalCdf(std::abs(r.z))));
  return r;
}

}  // namespace gib::metrics
