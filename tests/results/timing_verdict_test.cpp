// How a timing change is judged by history and by interleaved A/B runs: the rules `gibench diff`
// and a bisect rely on, on synthetic runs (deterministic: fixed seeds, fixed numbers).
#include "results/timing_verdict.h"
#include "results/results_diff.h"
#include "results/timing_history.h"

#include "metrics/distributions.h"
#include "metrics/timing_statistics.h"
#include "support/synthetic_results.h"

#include <fmt/format.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>

namespace gib::results {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

constexpr double kSignificance = 0.01;

JobResult timedJob(double median_ms, std::uint64_t seed) {
  return test::syntheticJob("cornell-direct", {{"relmse", 0.01}},
                            test::noisyFrameTimes(seed, 16, median_ms, 0.01));
}

// Per-run medians of `runs` runs whose spread between runs is `spread` (log-normal), around 10 ms.
std::vector<double> history(int runs, double spread, std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> noise(0.0, spread);
  std::vector<double> medians;
  for (int i = 0; i < runs; ++i) medians.push_back(10.0 * std::exp(noise(generator)));
  return medians;
}

TEST(TimingVerdict, AChangeOutsideTheRunToRunSpreadRegresses) {
  const TimingChange change =
      judgeTiming(timedJob(10.0, 1), timedJob(14.0, 2), history(10, 0.03, 3), {}, kSignificance);
  EXPECT_EQ(change.evidence, TimingEvidence::kHistory);
  EXPECT_EQ(change.history_runs, 10u);
  EXPECT_NEAR(change.run_to_run_spread, 0.03, 0.015);
  EXPECT_LT(change.p_value, kSignificance);
  EXPECT_EQ(change.verdict, Verdict::kRegressed);
  EXPECT_THAT(change.explanation(), HasSubstr("history of 10 comparable runs"));
}

// Frames within each run barely vary here (1%), so the two runs alone would call +25% certain;
// the history says runs of this job differ by 15% anyway.
TEST(TimingVerdict, AChangeInsideALargeRunToRunSpreadIsUnconfirmed) {
  const TimingChange change =
      judgeTiming(timedJob(10.0, 1), timedJob(12.5, 2), history(10, 0.15, 4), {}, kSignificance);
  EXPECT_EQ(change.evidence, TimingEvidence::kHistory);
  EXPECT_GT(change.p_value, kSignificance);
  EXPECT_EQ(change.verdict, Verdict::kUnconfirmed);
  EXPECT_GT(change.detectable_change, 0.25);
}

TEST(TimingVerdict, FasterOutsideTheSpreadImproves) {
  const TimingChange change =
      judgeTiming(timedJob(10.0, 1), timedJob(7.0, 2), history(10, 0.03, 5), {}, kSignificance);
  EXPECT_EQ(change.verdict, Verdict::kImproved);
}

TEST(TimingVerdict, TooLittleHistoryFallsBackToTheRunsThemselves) {
  const TimingChange change = judgeTiming(timedJob(10.0, 1), timedJob(14.0, 2),
                                          history(kMinHistoryRuns - 1, 0.03, 6), {}, kSignificance);
  EXPECT_EQ(change.evidence, TimingEvidence::kFrames);
  EXPECT_EQ(change.verdict, Verdict::kUnconfirmed);
}

// What an explanation prints of a test's p-value and detectable change.
std::string printedNumbers(const metrics::TimingTest& test) {
  return fmt::format("p = {:.2g} against significance {:.2g}; detects changes of {:.1f}% or more",
                     test.p_value, kSignificance, 100 * test.detectable_change);
}

// Repeats are the unit when both runs have them: a test over per-run medians, not frames. Here
// they disagree: each run's frames barely vary (1%), so frames alone would call the 6% slowdown
// certain (and the line would say "a real change"), while the repeats vary by ±15% and cannot
// tell it from noise. 6% is within the 10% tolerance either way: the evidence shows in the
// numbers the line prints.
TEST(TimingVerdict, RepeatsAreTestedRatherThanFrames) {
  JobResult base = timedJob(10.0, 1), next = timedJob(10.6, 2);
  const std::vector<double> base_medians = {10.0, 11.5, 8.7}, next_medians = {10.6, 12.2, 9.2};
  for (std::size_t i = 0; i < base_medians.size(); ++i) {
    base.repeats.push_back(*timedJob(base_medians[i], 7 + i).timings);
    next.repeats.push_back(*timedJob(next_medians[i], 17 + i).timings);
  }
  const metrics::TimingTest by_frames =
      metrics::testWithinRuns(base.frameSamplesMs(), next.frameSamplesMs(), kSignificance);
  const metrics::TimingTest by_repeats =
      metrics::testWithinRuns(base.repeatMediansMs(), next.repeatMediansMs(), kSignificance);
  ASSERT_LT(by_frames.p_value, kSignificance);  // the case is one where the two disagree
  ASSERT_GT(by_repeats.p_value, kSignificance);

  const TimingChange change = judgeTiming(base, next, {}, {}, kSignificance);
  EXPECT_EQ(change.evidence, TimingEvidence::kRepeats);
  EXPECT_EQ(change.base_samples, 3u);
  EXPECT_EQ(change.next_samples, 3u);
  EXPECT_EQ(change.p_value, by_repeats.p_value);
  EXPECT_EQ(change.detectable_change, by_repeats.detectable_change);
  EXPECT_EQ(change.verdict, Verdict::kUnchanged);
  EXPECT_THAT(change.explanation(), HasSubstr("3 + 3 repeats within the two runs only"));
  EXPECT_THAT(change.explanation(), HasSubstr(printedNumbers(by_repeats)));
  EXPECT_THAT(change.explanation(), Not(HasSubstr("a real change")));
}

TEST(TimingVerdict, InterleavedPairsConfirmARealSlowdownAndClearNoise) {
  TimingChange change = judgeTiming(timedJob(10.0, 1), timedJob(13.0, 2), {}, {}, kSignificance);
  ASSERT_EQ(change.verdict, Verdict::kUnconfirmed);
  ASSERT_TRUE(worthConfirming(change));
  // The machine drifts by ±20% from pair to pair; within a pair, the new build is 25% slower.
  const std::vector<double> drift = {1.0, 1.2, 0.85, 1.1, 0.9, 1.15, 0.95, 1.05, 1.1, 0.8};
  std::vector<double> a, b;
  for (std::size_t i = 0; i < drift.size(); ++i) {
    a.push_back(10.0 * drift[i] * (1 + 0.01 * double(i % 2)));
    b.push_back(12.5 * drift[i] * (1 - 0.01 * double(i % 3)));
  }
  TimingChange confirmed = change;
  confirmTiming(confirmed, a, b);
  EXPECT_EQ(confirmed.evidence, TimingEvidence::kConfirmation);
  EXPECT_NEAR(confirmed.relative_change, 0.25, 0.02);
  EXPECT_EQ(confirmed.verdict, Verdict::kRegressed);
  EXPECT_EQ(confirmed.pairs_base_ms, a);
  // The same drift with no change between the builds: within tolerance, with the power stated.
  std::vector<double> same;
  for (std::size_t i = 0; i < a.size(); ++i)
    same.push_back(a[i] * (1 + 0.01 * double(i % 3) - 0.01));
  TimingChange cleared = change;
  confirmTiming(cleared, a, same);
  EXPECT_EQ(cleared.verdict, Verdict::kUnchanged);
  EXPECT_THAT(cleared.explanation(), HasSubstr("detects changes of"));
}

// A 6% slowdown that 18 interleaved pairs see clearly is within the 10% tolerance: unchanged, but
// named as a real change, so a user reading the line does not take it for "the same".
TEST(TimingVerdict, ARealChangeWithinToleranceIsNamed) {
  TimingChange change = judgeTiming(timedJob(10.0, 1), timedJob(10.6, 2), {}, {}, kSignificance);
  std::vector<double> a, b;
  for (int i = 0; i < 18; ++i) {
    const double machine = 1.0 + 0.02 * double(i % 5);
    a.push_back(10.0 * machine);
    b.push_back(10.6 * machine * (1 + 0.003 * double(i % 3)));
  }
  confirmTiming(change, a, b);
  EXPECT_EQ(change.verdict, Verdict::kUnchanged);
  EXPECT_LT(change.p_value, change.significance);
  EXPECT_THAT(change.explanation(), HasSubstr("a real change, within the 10.0% tolerance"));
  // Pairs that see nothing say nothing of the kind.
  TimingChange same = judgeTiming(timedJob(10.0, 1), timedJob(10.6, 2), {}, {}, kSignificance);
  confirmTiming(same, a, a);
  EXPECT_THAT(same.explanation(), Not(HasSubstr("real change")));
}

// A change of 5%, under the 10% tolerance, is reported unchanged only with the smallest change
// the evidence would have caught, never as a bare "unchanged". The evidence is the history, not
// the frames (1% apart, which would call 5% a real change): the line's numbers are the history
// test's, written out here from its definition (metrics/timing_statistics.h). Runs 8% apart see
// only changes of 74% or more, so interleaved A/B runs are worth trying (worthConfirming); runs
// under 1% apart see 6%, within the tolerance, and name the 5% as a real change: they are not.
TEST(TimingVerdict, UnchangedSaysWhatTheEvidenceCouldHaveSeen) {
  const JobResult base = timedJob(10.0, 1), next = timedJob(10.5, 2);
  for (const auto& [spread, worth_confirming] : {std::pair{0.05, true}, std::pair{0.005, false}}) {
    SCOPED_TRACE(spread);
    const std::vector<double> runs = history(10, spread, 9);
    const TimingChange change = judgeTiming(base, next, runs, {}, kSignificance);
    EXPECT_EQ(change.evidence, TimingEvidence::kHistory);
    EXPECT_EQ(change.verdict, Verdict::kUnchanged);
    // Student's t on ln(median) with the history's spread s: ln(new/base) / (s·√2), 9 degrees
    // of freedom; detectable: (t₀.₉₉₅ + t₀.₉₅)·s·√2.
    double mean = 0, squares = 0;
    for (double run : runs) mean += std::log(run) / double(runs.size());
    for (double run : runs) squares += (std::log(run) - mean) * (std::log(run) - mean);
    const double se = std::sqrt(squares / double(runs.size() - 1)) * std::sqrt(2.0);
    const double dof = double(runs.size() - 1);
    metrics::TimingTest expected;
    expected.p_value =
        2 * (1 - metrics::studentTCdf(
                     std::abs(std::log(*next.runMedianMs() / *base.runMedianMs())) / se, dof));
    expected.detectable_change = std::exp((metrics::studentTQuantile(1 - kSignificance / 2, dof) +
                                           metrics::studentTQuantile(0.95, dof)) *
                                          se) -
                                 1;
    EXPECT_NEAR(change.p_value, expected.p_value, 1e-9);
    EXPECT_NEAR(change.detectable_change, expected.detectable_change, 1e-9);
    const std::string line = change.explanation();
    EXPECT_THAT(line, HasSubstr("history of 10 comparable runs"));
    EXPECT_THAT(line, HasSubstr(printedNumbers(expected)));
    EXPECT_EQ(line.find("a real change") != std::string::npos, expected.p_value < kSignificance);
    ASSERT_EQ(expected.detectable_change > change.tolerance.relative, worth_confirming);
    EXPECT_EQ(worthConfirming(change), worth_confirming);
  }
}

// The history is the job's comparable runs only: another host or other parameters are not the
// same measurement, and the two compared runs are not their own history.
TEST(TimingHistory, KeepsComparableEarlierRunsOnly) {
  std::vector<RunResults> runs;
  for (int i = 0; i < 6; ++i) {
    RunResults run = test::syntheticRun("run-" + std::to_string(i), {timedJob(10.0 + i, 10 + i)});
    run.run.started = "2026-11-2" + std::to_string(i) + "T10:00:00Z";
    run.run.host = i == 3 ? "another-host" : "host";
    runs.push_back(run);
  }
  runs[4].jobs[0].parameters = {{"shadow", "vsm"}};
  const TimingHistory history = timingHistoryOf(runs, runs[1], runs[5]);
  ASSERT_EQ(history.count("cornell-direct"), 1u);
  // Runs 0 and 2: run 1 and 5 are compared, 3 ran elsewhere, 4 measured something else.
  EXPECT_EQ(history.at("cornell-direct").size(), 2u);
  // A later base leaves out what came after the newer run.
  EXPECT_EQ(timingHistoryOf(runs, runs[0], runs[1]).at("cornell-direct").size(), 0u);
}

TEST(ResultsDiff, TimingSignificanceIsSidakCorrectedOverTheDiffsTimings) {
  std::vector<JobResult> jobs;
  for (int i = 0; i < 4; ++i) {
    JobResult job = timedJob(10.0, std::uint64_t(20 + i));
    job.id = "job-" + std::to_string(i);
    jobs.push_back(job);
  }
  const RunResults base = test::syntheticRun("base", jobs);
  const RunResults next = test::syntheticRun("next", jobs);
  const DiffReport diff = diffResults(base, next);
  ASSERT_EQ(diff.timings.size(), 4u);
  EXPECT_NEAR(diff.timing_comparison_significance, 1 - std::pow(1 - 0.01, 0.25), 1e-12);
  EXPECT_EQ(diff.timings[0].significance, diff.timing_comparison_significance);
}

}  // namespace
}  // namespace gib::results
