#include "metrics/timing_statistics.h"

#include "metrics/distributions.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <mutex>
#include <numeric>
#include <random>
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

// 1.4826·MAD about the median: the standard deviation of normal samples, robust to outliers.
double robustScale(std::span<const double> x) {
  const double center = quantile(x, 0.5);
  std::vector<double> deviations;
  for (double v : x) deviations.push_back(std::abs(v - center));
  return 1.4826 * quantile(deviations, 0.5);
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

namespace {

// The distribution of the sum of positive ranks under "no change" (each sign ±1 with probability
// ½): element s is its probability of being s, for integer `ranks`.
std::vector<double> signedRankNullDistribution(const std::vector<int>& ranks) {
  const int total = std::accumulate(ranks.begin(), ranks.end(), 0);
  std::vector<double> probability(std::size_t(total) + 1, 0.0);
  probability[0] = 1.0;
  int reach = 0;
  for (int r : ranks) {
    reach += r;
    for (int s = reach; s >= 0; --s)
      probability[std::size_t(s)] = 0.5 * probability[std::size_t(s)] +
                                    (s >= r ? 0.5 * probability[std::size_t(s - r)] : 0.0);
  }
  return probability;
}

}  // namespace

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
  // Step 2: the distribution of W⁺ (doubled: integer ranks) under "no change".
  int positive = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (d[i] > 0) positive += rank2[i];
  const std::vector<double> probability = signedRankNullDistribution(rank2);
  // Step 3: both tails.
  double below = 0, above = 0;
  for (std::size_t s = 0; s < probability.size(); ++s) {
    if (int(s) <= positive) below += probability[s];
    if (int(s) >= positive) above += probability[s];
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

namespace {

// The shift of ln(b/a), in units of the differences' robust scale, that the exact signed-rank
// test of `pairs` normal differences detects with probability kDetectionPower at
// `significance`: infinite when it can reject nothing. Its power has no closed form at these
// sizes, so it is simulated (a fixed seed: the same answer every time). The normal
// approximation with the test's asymptotic efficiency (3/π of the t-test's), used before,
// promised 95% where the test reached 80% with 16 pairs and 57% with 9.
double signedRankDetectableShift(std::size_t pairs, double significance) {
  // Computed once per (pairs, significance): a diff asks for one, the tests for a few.
  static std::mutex mutex;
  static std::map<std::pair<std::size_t, double>, double> known;
  const std::lock_guard lock(mutex);
  const auto [at, is_new] = known.try_emplace({pairs, significance}, 0.0);
  if (!is_new) return at->second;
  // Step 1: the least W⁺ (untied) the test rejects at: that many Walsh averages above zero.
  std::vector<int> ranks(pairs);
  std::iota(ranks.begin(), ranks.end(), 1);
  const std::vector<double> null = signedRankNullDistribution(ranks);
  std::size_t least = null.size();  // none: too few pairs for any p-value under `significance`
  double tail = 0;                  // P(W⁺ ≥ w)
  for (std::size_t w = null.size(); w-- > 0;) {
    tail += null[w];
    if (2.0 * tail >= significance) break;
    least = w;
  }
  if (least == null.size()) return at->second = std::numeric_limits<double>::infinity();
  // Step 2: per sample z of n standard normal differences, the shift h, in units of the
  // sample's robust scale, at which its `least`-th largest Walsh average crosses zero: the test
  // of z + h·scale(z) rejects (on the upper side) for every larger h, so the 95% quantile of h
  // over samples is the shift detected 95% of the time. (Rejections on the lower side at such a
  // shift, nearly every difference negative, are negligible and left out.)
  constexpr int kSamples = 20000;  // the power at that quantile within ±0.3% (two std. errors)
  std::mt19937_64 generator(20261122);
  std::normal_distribution<double> normal;
  std::vector<double> z(pairs), walsh, shifts;
  for (int sample = 0; sample < kSamples; ++sample) {
    for (double& x : z) x = normal(generator);
    walsh.clear();
    for (std::size_t i = 0; i < pairs; ++i)
      for (std::size_t j = i; j < pairs; ++j) walsh.push_back(0.5 * (z[i] + z[j]));
    const auto kth = walsh.begin() + std::ptrdiff_t(least - 1);
    std::nth_element(walsh.begin(), kth, walsh.end(), std::greater<>());
    shifts.push_back(-*kth / robustScale(z));
  }
  return at->second = quantile(shifts, kDetectionPower);
}

}  // namespace

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
  // The detectable change: the shift the test detects with 95% power among differences of this
  // robust scale (which a shift leaves as it is).
  const double shift = signedRankDetectableShift(d.size(), significance);
  test.detectable_change = std::isinf(shift) ? shift : std::exp(shift * robustScale(d)) - 1.0;
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
