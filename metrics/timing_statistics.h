// Robust summaries of timing samples, and the tests that tell a change of a timing from noise:
// these machines are shared and noisy, so medians for summaries, and tests of log ratios whose
// unit is a whole run (against the spread between runs, or in interleaved A/B pairs) rather than
// the frames of one run, which see nothing of the drift between runs.
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

// A timing comparison of two settings (a base and a new build) by one kind of evidence, in the
// log domain: times are positive and their noise multiplicative, so a ratio is the natural
// measure and ln(time) is close to normal on these machines.
struct TimingTest {
  double ratio = 1;    // estimated new / base
  double p_value = 1;  // two-sided, for "no change"
  double degrees_of_freedom = 0;
  // The smallest relative change (|ratio − 1|) this evidence detects with probability
  // `kDetectionPower` at the test's significance: what "unchanged" means.
  double detectable_change = 0;
};

// The power at which TimingTest::detectable_change is stated.
inline constexpr double kDetectionPower = 0.95;

// The spread of per-run medians: exp(s) − 1 for s the sample standard deviation of their logs
// (a relative one-sigma spread). Needs two or more runs.
double runToRunSpread(std::span<const double> run_medians_ms);

// Two runs against the run-to-run spread of comparable earlier runs (`history_ms`, per-run
// medians): under "no change", ln(new) − ln(base) is the difference of two draws of the runs'
// distribution, so ln(new/base) / (s·√2) follows Student's t with k − 1 degrees of freedom, s the
// sample standard deviation of ln(history). Needs two or more history runs
// (std::invalid_argument otherwise).
TimingTest testAgainstRunToRunSpread(double base_ms, double new_ms,
                                     std::span<const double> history_ms, double significance);

// Interleaved A/B pairs (a_i run right before b_i on one machine): the exact Wilcoxon
// signed-rank test of ln(b_i / a_i), with the Hodges–Lehmann estimate of the ratio. Pairing
// cancels the slow drift of the machine's state that makes two separate runs differ; ranks keep
// the odd run that landed in another scheduling mode of the software rasterizer (a third faster
// or slower) from deciding the verdict, as it would decide a t-test. With n pairs the smallest
// p-value is 2/2ⁿ: fewer pairs than that allows at `significance` detect nothing (infinite
// detectable change). Needs two or more pairs of equal length (std::invalid_argument otherwise).
TimingTest testInterleavedPairs(std::span<const double> a_ms, std::span<const double> b_ms,
                                double significance);

// The exact two-sided p-value of the Wilcoxon signed-rank statistic of `differences` (zeros left
// out, tied magnitudes given their average rank); 1 when none is left.
double wilcoxonSignedRankP(std::span<const double> differences);

// The fewest interleaved pairs whose signed-rank test reaches `significance` even when the pair of
// smallest difference goes the other way: 2ⁿ ≥ 4 / significance.
int pairsFor(double significance);

// The pairs `gibench diff --confirm` runs by default: the fewest whose test still reaches
// `significance` when the pair of largest difference (one run caught by a hiccup of the machine,
// or in another scheduling mode of the software rasterizer) and the pair of smallest difference
// both go the other way; 16 at 0.01, 18 at a diff's per-comparison significance with three timed
// jobs. With two pairs fewer, one such pair in sixteen hid a 25% slowdown from the test in 2
// of 21 measured comparisons (docs/harness.md, "Timing verdicts").
int recommendedPairs(double significance);

// Two independent samples of per-repeat (or per-frame) times of two runs: Welch's t-test of the
// logs. It sees only the noise within each run, not the drift between runs, so the harness takes
// it as a hint, never as proof of a regression. Needs two or more of each.
TimingTest testWithinRuns(std::span<const double> base_ms, std::span<const double> new_ms,
                          double significance);

}  // namespace gib::metrics
