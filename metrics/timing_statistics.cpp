#include "metrics/timing_statistics.h"

#include "metrics/distributions.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
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

}  // namespace gib::metrics

namespace gib::metrics {

namespace {

std::vector<double> logs(std::span<const double> samples) {
  std::vector<double> out;
  out.reserve(samples.size());
  for (double x : samples) {
    if (!(x > 0) || !std::isfinite(x))
      throw std::invalid_argument("timing samples must be positive and finite");
    out.push_back(std::log(x));
  }
  return out;
}

double mean(const std::vector<double>& x) {
  return std::accumulate(x.begin(), x.end(), 0.0) / double(x.size());
}

double sampleVariance(const std::vector<double>& x) {
  const double m = mean(x);
  double sum = 0;
  for (double v : x) sum += (v - m) * (v - m);
  return sum / double(x.size() - 1);
}

// The test of an estimated log ratio with standard error `se` on `dof` degrees of freedom.
TimingTest tTest(double log_ratio, double se, double dof, double significance) {
  TimingTest test;
  test.ratio = std::exp(log_ratio);
  test.degrees_of_freedom = dof;
  const double critical = studentTQuantile(1.0 - 0.5 * significance, dof);
  const double power = studentTQuantile(kDetectionPower, dof);
  test.detectable_change = std::exp((critical + power) * se) - 1.0;
  if (se > 0) {
    const double t = std::abs(log_ratio) / se;
    test.p_value = 2.0 * (1.0 - studentTCdf(t, dof));
  } else {
    test.p_value = log_ratio == 0 ? 1.0 : 0.0;
  }
  return test;
}

}  // namespace

double runToRunSpread(std::span<const double> run_medians_ms) {
  if (run_medians_ms.size() < 2)
    throw std::invalid_argument("a run-to-run spread needs two or more runs");
  return std::exp(std::sqrt(sampleVariance(logs(run_medians_ms)))) - 1.0;
}

TimingTest testAgainstRunToRunSpread(double base_ms, double new_ms,
                                     std::span<const double> history_ms, double significance) {
  if (history_ms.size() < 2)
    throw std::invalid_argument("the run-to-run spread needs two or more earlier runs");
  const std::vector<double> x = logs(history_ms);
  const double s = std::sqrt(sampleVariance(x));
  const double base = std::log(base_ms), next = std::log(new_ms);
  return tTest(next - base, s * std::sqrt(2.0), double(x.size() - 1), significance);
}

double wilcoxonSignedRankP(std::span<const double> differences) {
  // Step 1: the nonzero differences by magnitude, with doubled average ranks (integers).
  std::vector<double> d;
  for (double x : differences)
    if (x != 0) d.push_back(x);
  if (d.empty()) return 1.0;
  std::sort(d.begin(), d.end(), [](double x, double y) { return std::abs(x) < std::abs(y); });
  const std::size_t n = d.size();
  std::vector<int> rank2(n);
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;
    while (j + 1 < n && std::abs(d[j + 1]) == std::abs(d[i])) ++j;
    for (std::size_t k = i; k <= j; ++k) rank2[k] = int(i + j + 2);  // twice the average rank
    i = j + 1;
  }
  // Step 2: the distribution of W⁺ (doubled) under "no change": each sign ±1 with probability ½.
  int total = 0, positive = 0;
  for (std::size_t i = 0; i < n; ++i) {
    total += rank2[i];
    if (d[i] > 0) positive += rank2[i];
  }
  std::vector<double> probability(std::size_t(total) + 1, 0.0);
  probability[0] = 1.0;
  int reach = 0;
  for (int r : rank2) {
    reach += r;
    for (int s = reach; s >= 0; --s)
      probability[std::size_t(s)] = 0.5 * probability[std::size_t(s)] +
                                    (s >= r ? 0.5 * probability[std::size_t(s - r)] : 0.0);
  }
  // Step 3: both tails.
  double below = 0, above = 0;
  for (int s = 0; s <= total; ++s) {
    if (s <= positive) below += probability[std::size_t(s)];
    if (s >= positive) above += probability[std::size_t(s)];
  }
  return std::min(1.0, 2.0 * std::min(below, above));
}

int pairsFor(double significance) {
  int n = 2;
  while (std::ldexp(1.0, n) < 4.0 / significance) ++n;
  return n;
}

int recommendedPairs(double significance) {
  // The worst single hiccup is the pair of largest difference going the other way; the pair of
  // smallest difference, lost in the noise, may go with it.
  for (int n = pairsFor(significance);; ++n) {
    std::vector<double> d;
    for (int rank = 1; rank <= n; ++rank) d.push_back(rank == 1 || rank == n ? -rank : rank);
    if (wilcoxonSignedRankP(d) <= significance) return n;
  }
}

TimingTest testInterleavedPairs(std::span<const double> a_ms, std::span<const double> b_ms,
                                double significance) {
  if (a_ms.size() != b_ms.size() || a_ms.size() < 2)
    throw std::invalid_argument("interleaved pairs need two or more (a, b) pairs");
  const std::vector<double> a = logs(a_ms), b = logs(b_ms);
  std::vector<double> d;
  for (std::size_t i = 0; i < a.size(); ++i) d.push_back(b[i] - a[i]);
  // The Hodges–Lehmann shift: the median of the Walsh averages (d_i + d_j) / 2, i ≤ j.
  std::vector<double> walsh;
  for (std::size_t i = 0; i < d.size(); ++i)
    for (std::size_t j = i; j < d.size(); ++j) walsh.push_back(0.5 * (d[i] + d[j]));
  TimingTest test;
  test.ratio = std::exp(quantile(walsh, 0.5));
  test.p_value = wilcoxonSignedRankP(d);
  test.degrees_of_freedom = double(d.size());
  // The detectable change: the normal approximation of the signed-rank test (efficiency 3/π of
  // the t-test for normal noise) with a robust scale, 1.4826·MAD; none below the exact floor.
  const double n = double(d.size());
  if (2.0 / std::ldexp(1.0, int(d.size())) >= significance) {
    test.detectable_change = std::numeric_limits<double>::infinity();
  } else {
    const double center = quantile(d, 0.5);
    std::vector<double> deviations;
    for (double x : d) deviations.push_back(std::abs(x - center));
    const double scale = 1.4826 * quantile(deviations, 0.5);
    const double se = scale / std::sqrt(n * 3.0 / std::numbers::pi);
    test.detectable_change =
        std::exp((normalQuantile(1.0 - 0.5 * significance) + normalQuantile(kDetectionPower)) *
                 se) -
        1.0;
  }
  return test;
}

TimingTest testWithinRuns(std::span<const double> base_ms, std::span<const double> new_ms,
                          double significance) {
  if (base_ms.size() < 2 || new_ms.size() < 2)
    throw std::invalid_argument("a within-run comparison needs two or more samples of each");
  const std::vector<double> a = logs(base_ms), b = logs(new_ms);
  const double va = sampleVariance(a) / double(a.size()), vb = sampleVariance(b) / double(b.size());
  const double se = std::sqrt(va + vb);
  // Welch–Satterthwaite degrees of freedom.
  double dof = double(a.size() + b.size() - 2);
  if (va + vb > 0)
    dof = (va + vb) * (va + vb) / (va * va / double(a.size() - 1) + vb * vb / double(b.size() - 1));
  return tTest(mean(b) - mean(a), se, dof, significance);
}

}  // namespace gib::metrics
