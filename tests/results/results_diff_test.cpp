// `gibench diff`'s decisions on synthetic results: what a user bisecting a regression relies on
// being flagged, and the noise that must not be.
#include "results/results_diff.h"

#include "metrics/timing_statistics.h"
#include "support/synthetic_results.h"

#include <fmt/format.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

namespace gib::results {
namespace {

using ::testing::HasSubstr;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kFrames = 16;

RunResults runWith(const std::string& id, const NamedValues& metrics,
                   const std::vector<double>& frames = {}) {
  return test::syntheticRun(id, {test::syntheticJob("cornell-direct", metrics, frames)});
}

// The verdict of the only metric value compared between runs of one job.
Verdict metricVerdict(const NamedValues& base, const NamedValues& next,
                      const Tolerances& tolerances = {}) {
  RunResults next_run = runWith("next", next);
  next_run.tolerances = tolerances;
  const DiffReport diff = diffResults(runWith("base", base), next_run);
  EXPECT_EQ(diff.metrics.size(), 1u);
  return diff.metrics.empty() ? Verdict::kUnchanged : diff.metrics[0].verdict;
}

std::vector<double> scaled(std::vector<double> samples, double factor) {
  for (double& s : samples) s *= factor;
  return samples;
}

TimingChange timingChange(const std::vector<double>& base, const std::vector<double>& next) {
  const DiffReport diff = diffResults(runWith("base", {}, base), runWith("next", {}, next));
  EXPECT_EQ(diff.timings.size(), 1u);
  return diff.timings.empty() ? TimingChange{} : diff.timings[0];
}

TEST(ResultsDiff, TenPercentMoreErrorIsARegressionWithTheDefaultTolerance) {
  const DiffReport diff =
      diffResults(runWith("base", {{"relmse", 0.0200}}), runWith("next", {{"relmse", 0.0220}}));
  ASSERT_EQ(diff.metrics.size(), 1u);
  EXPECT_EQ(diff.metrics[0].verdict, Verdict::kRegressed);
  EXPECT_NEAR(diff.metrics[0].relative_change, 0.10, 1e-12);
  EXPECT_EQ(diff.metrics[0].job, "cornell-direct");
  EXPECT_EQ(diff.metrics[0].metric, "relmse");
  EXPECT_EQ(diff.regressions(), 1u);
  EXPECT_EQ(diff.improvements(), 0u);
}

TEST(ResultsDiff, NoiseWithinToleranceIsUnchanged) {
  EXPECT_EQ(metricVerdict({{"relmse", 0.0200}}, {{"relmse", 0.0204}}), Verdict::kUnchanged);
  EXPECT_EQ(metricVerdict({{"relmse", 0.0200}}, {{"relmse", 0.0196}}), Verdict::kUnchanged);
  EXPECT_EQ(metricVerdict({{"flip_mean", 0.1}}, {{"flip_mean", 0.1}}), Verdict::kUnchanged);
}

TEST(ResultsDiff, LessErrorIsAnImprovementNotARegression) {
  const DiffReport diff = diffResults(runWith("base", {{"relmse", 0.02}, {"flip_mean", 0.2}}),
                                      runWith("next", {{"relmse", 0.015}, {"flip_mean", 0.1}}));
  EXPECT_EQ(diff.regressions(), 0u);
  EXPECT_EQ(diff.improvements(), 2u);
}

TEST(ResultsDiff, LowerSsimAndPsnrAreRegressions) {
  EXPECT_EQ(metricVerdict({{"ssim", 0.95}}, {{"ssim", 0.85}}), Verdict::kRegressed);
  EXPECT_EQ(metricVerdict({{"ssim", 0.85}}, {{"ssim", 0.95}}), Verdict::kImproved);
  EXPECT_EQ(metricVerdict({{"psnr", 40}}, {{"psnr", 30}}), Verdict::kRegressed);
}

TEST(ResultsDiff, EnergyRatioIsJudgedByItsDistanceFromOne) {
  // Gaining light is as wrong as losing it: 1.0 → 1.2 and 1.0 → 0.8 regress, 0.8 → 0.95 and
  // 1.2 → 1.05 improve.
  EXPECT_EQ(metricVerdict({{"energy_ratio", 1.0}}, {{"energy_ratio", 1.2}}), Verdict::kRegressed);
  EXPECT_EQ(metricVerdict({{"energy_ratio", 1.0}}, {{"energy_ratio", 0.8}}), Verdict::kRegressed);
  EXPECT_EQ(metricVerdict({{"energy_ratio", 0.8}}, {{"energy_ratio", 0.95}}), Verdict::kImproved);
  EXPECT_EQ(metricVerdict({{"energy_ratio", 1.2}}, {{"energy_ratio", 1.05}}), Verdict::kImproved);
}

// How concentrated relMSE is describes the error, with no better direction: a bisect must not
// stop at a commit that merely moved the error between pixels.
TEST(ResultsDiff, ConcentrationSharesNeverRegressOrImprove) {
  EXPECT_EQ(metricVerdict({{"relmse_top1pct_share", 0.39}}, {{"relmse_top1pct_share", 0.36}}),
            Verdict::kUnchanged);
  EXPECT_EQ(metricVerdict({{"relmse_top0p1pct_share", 0.1}}, {{"relmse_top0p1pct_share", 0.9}}),
            Verdict::kUnchanged);
  // relMSE without the worst pixels is an error like any other.
  EXPECT_EQ(metricVerdict({{"relmse_trim1pct", 0.01}}, {{"relmse_trim1pct", 0.02}}),
            Verdict::kRegressed);
}

TEST(ResultsDiff, FullReferenceValuesAreComparedUnderTheirOwnName) {
  RunResults base = runWith("base", {{"relmse", 0.02}});
  RunResults next = runWith("next", {{"relmse", 0.02}});
  base.jobs[0].metrics_full = {{"relmse", 0.30}, {"ssim", 0.80}};
  next.jobs[0].metrics_full = {{"relmse", 0.40}, {"ssim", 0.90}};
  next.tolerances.metrics["relmse"] = {0, 0.5};  // "full:relmse" takes relmse's tolerance
  const DiffReport diff = diffResults(base, next);
  ASSERT_EQ(diff.metrics.size(), 3u);
  EXPECT_EQ(diff.metrics[1].metric, "full:relmse");
  EXPECT_EQ(diff.metrics[1].verdict, Verdict::kUnchanged);
  EXPECT_EQ(diff.metrics[2].metric, "full:ssim");
  EXPECT_EQ(diff.metrics[2].verdict, Verdict::kImproved);
}

TEST(ResultsDiff, NonFiniteValuesAreJudgedByWhatTheyMean) {
  EXPECT_EQ(metricVerdict({{"relmse", 0.02}}, {{"relmse", kNaN}}), Verdict::kRegressed);
  EXPECT_EQ(metricVerdict({{"relmse", 0.02}}, {{"relmse", kInf}}), Verdict::kRegressed);
  EXPECT_EQ(metricVerdict({{"ssim", 0.9}}, {{"ssim", kNaN}}), Verdict::kRegressed);
  EXPECT_EQ(metricVerdict({{"relmse", kNaN}}, {{"relmse", 0.02}}), Verdict::kImproved);
  EXPECT_EQ(metricVerdict({{"relmse", kNaN}}, {{"relmse", kNaN}}), Verdict::kUnchanged);
  // A PSNR of +inf is an exact image: losing it is a regression, whatever the tolerance.
  EXPECT_EQ(metricVerdict({{"psnr", kInf}}, {{"psnr", 60}}), Verdict::kRegressed);
  EXPECT_EQ(metricVerdict({{"psnr", kInf}}, {{"psnr", kInf}}), Verdict::kUnchanged);
}

TEST(ResultsDiff, AbsoluteToleranceCoversValuesNearZero) {
  Tolerances tolerances;
  EXPECT_EQ(metricVerdict({{"relmse", 0}}, {{"relmse", 1e-9}}, tolerances), Verdict::kRegressed);
  tolerances.metric_default = {1e-6, 0.05};
  EXPECT_EQ(metricVerdict({{"relmse", 0}}, {{"relmse", 1e-9}}, tolerances), Verdict::kUnchanged);
  // Zero tolerance: only a bit-identical value is unchanged.
  tolerances.metric_default = {0, 0};
  EXPECT_EQ(metricVerdict({{"relmse", 0.02}}, {{"relmse", 0.02}}, tolerances), Verdict::kUnchanged);
  EXPECT_EQ(metricVerdict({{"relmse", 0.02}}, {{"relmse", 0.020000000000000004}}, tolerances),
            Verdict::kRegressed);
}

TEST(ResultsDiff, TheNewRunsSuiteToleranceDecides) {
  Tolerances loose;
  loose.metrics["relmse"] = {0, 0.15};
  EXPECT_EQ(metricVerdict({{"relmse", 0.02}}, {{"relmse", 0.022}}, loose), Verdict::kUnchanged);
  // Only relmse is loosened; the default still holds for flip_mean.
  EXPECT_EQ(metricVerdict({{"flip_mean", 0.1}}, {{"flip_mean", 0.11}}, loose), Verdict::kRegressed);
  Tolerances strict;
  strict.metric_default = {0, 0.01};
  EXPECT_EQ(metricVerdict({{"relmse", 0.02}}, {{"relmse", 0.0204}}, strict), Verdict::kRegressed);
}

// Two runs alone only show the noise within them (frames here): a timing change beyond tolerance
// that they find significant is "unconfirmed", never a regression, because runs minutes apart on
// one machine differ by more than that (results/timing_verdict.h; with history or --confirm in
// timing_verdict_test.cpp). The seeds are fixed, so each case is deterministic.
TEST(ResultsDiff, ThirtyPercentSlowerFramesAloneAreUnconfirmed) {
  const std::vector<double> base = test::noisyFrameTimes(11, kFrames, 8.0);
  const TimingChange change =
      timingChange(base, scaled(test::noisyFrameTimes(12, kFrames, 8.0), 1.3));
  EXPECT_EQ(change.verdict, Verdict::kUnconfirmed);
  EXPECT_EQ(change.evidence, TimingEvidence::kFrames);
  EXPECT_NEAR(change.relative_change, 0.3, 0.05);
  EXPECT_LT(change.p_value, 1e-5);
  EXPECT_THAT(change.explanation(), HasSubstr("--confirm"));
}

TEST(ResultsDiff, StrictTimingCountsAnUnconfirmedSlowdown) {
  const RunResults base = runWith("base", {}, test::noisyFrameTimes(11, kFrames, 8.0));
  const RunResults next = runWith("next", {}, scaled(test::noisyFrameTimes(12, kFrames, 8.0), 1.3));
  EXPECT_EQ(diffResults(base, next).regressions(), 0u);
  DiffOptions strict;
  strict.strict_timing = true;
  EXPECT_EQ(diffResults(base, next, strict).regressions(), 1u);
  // A faster run is never counted, strict or not.
  EXPECT_EQ(diffResults(next, base, strict).regressions(), 0u);
}

// Unchanged by the 10% tolerance; the line says what the frames could have seen, by Welch's test
// of the two runs' frames (metrics::testWithinRuns, written out in timing_statistics_test.cpp).
TEST(ResultsDiff, FramesFromTheSameDistributionAreUnchanged) {
  const std::vector<double> base = test::noisyFrameTimes(21, kFrames, 8.0);
  const std::vector<double> next = test::noisyFrameTimes(22, kFrames, 8.0);
  const TimingChange change = timingChange(base, next);
  const metrics::TimingTest expected = metrics::testWithinRuns(base, next, change.significance);
  EXPECT_EQ(change.evidence, TimingEvidence::kFrames);
  EXPECT_EQ(change.verdict, Verdict::kUnchanged);
  EXPECT_GT(expected.p_value, change.significance);  // noise, which the test does not reject
  EXPECT_EQ(change.p_value, expected.p_value);
  EXPECT_EQ(change.detectable_change, expected.detectable_change);
  const std::string line = change.explanation();
  EXPECT_THAT(line, HasSubstr("16 + 16 frames within the two runs only"));
  EXPECT_THAT(line, HasSubstr(fmt::format("p = {:.2g} against", expected.p_value)));
  EXPECT_THAT(line, HasSubstr(fmt::format("detects changes of {:.1f}% or more",
                                          100 * expected.detectable_change)));
}

TEST(ResultsDiff, SignificantFivePercentIsUnderTheTimingThreshold) {
  const TimingChange change =
      timingChange(test::noisyFrameTimes(31, kFrames, 8.0, 0.01),
                   scaled(test::noisyFrameTimes(32, kFrames, 8.0, 0.01), 1.05));
  EXPECT_LT(change.p_value, 0.01);                 // the test sees it ...
  EXPECT_EQ(change.verdict, Verdict::kUnchanged);  // ... but 5% is below the 10% threshold
}

TEST(ResultsDiff, LargeChangeInTooFewFramesIsUnconfirmed) {
  const TimingChange change = timingChange({8.0, 9.0}, {11.0, 12.0});
  EXPECT_GT(change.relative_change, 0.2);
  EXPECT_GT(change.p_value, change.significance);
  EXPECT_EQ(change.verdict, Verdict::kUnconfirmed);
}

TEST(ResultsDiff, JobsWithoutFrameSamplesHaveNoTimingChange) {
  const DiffReport diff =
      diffResults(runWith("base", {{"relmse", 1}}), runWith("next", {{"relmse", 1}}, {8, 9, 10}));
  EXPECT_TRUE(diff.timings.empty());
}

TEST(ResultsDiff, MissingJobIsARegressionAndANewJobIsNot) {
  RunResults base = test::syntheticRun(
      "base", {test::syntheticJob("a", {{"relmse", 1}}), test::syntheticJob("b", {{"relmse", 1}})});
  RunResults next = test::syntheticRun(
      "next", {test::syntheticJob("a", {{"relmse", 1}}), test::syntheticJob("c", {{"relmse", 1}})});
  const DiffReport diff = diffResults(base, next);
  ASSERT_EQ(diff.presence.size(), 2u);
  EXPECT_EQ(diff.presence[0].job, "b");
  EXPECT_EQ(diff.presence[0].verdict, Verdict::kMissing);
  EXPECT_EQ(diff.presence[1].job, "c");
  EXPECT_EQ(diff.presence[1].verdict, Verdict::kAdded);
  EXPECT_EQ(diff.regressions(), 1u);
}

TEST(ResultsDiff, JobsLeftOutOfAPartialRunAreNotRegressions) {
  RunResults base = test::syntheticRun(
      "base", {test::syntheticJob("a", {{"relmse", 1}}), test::syntheticJob("b", {{"relmse", 1}})});
  RunResults next = test::syntheticRun("next", {test::syntheticJob("a", {{"relmse", 1}})});
  next.run.complete = false;  // `gibench run --only a`, as a bisect step runs it
  const DiffReport diff = diffResults(base, next);
  ASSERT_EQ(diff.presence.size(), 1u);
  EXPECT_EQ(diff.presence[0].verdict, Verdict::kNotRun);
  EXPECT_EQ(diff.regressions(), 0u);
  EXPECT_THAT(formatDiff(diff), HasSubstr("1 not run (the new run ran part of its suite)"));
  next.jobs[0].metrics[0].second = 2;  // what it did run is still judged
  EXPECT_EQ(diffResults(base, next).regressions(), 1u);
}

TEST(ResultsDiff, FormatListsChangesAndASummary) {
  RunResults base =
      test::syntheticRun("run-1", {test::syntheticJob("a", {{"relmse", 0.02}, {"ssim", 0.9}}),
                                   test::syntheticJob("gone", {{"relmse", 1}})});
  RunResults next =
      test::syntheticRun("run-2", {test::syntheticJob("a", {{"relmse", 0.03}, {"ssim", 0.9}})});
  const std::string text = formatDiff(diffResults(base, next));
  EXPECT_THAT(text, HasSubstr("base run-1\nnew  run-2\n"));
  EXPECT_THAT(text, HasSubstr("regressed   a  relmse  0.02 -> 0.03  +50.0%"));
  EXPECT_THAT(text, HasSubstr("missing     gone"));
  EXPECT_THAT(text, HasSubstr("2 regressions, 0 improvements, 0 unconfirmed, 1 unchanged, 0 "
                              "added; timing false-regression rate at most 0.01 per diff\n"));
  EXPECT_EQ(text.find("ssim"), std::string::npos);  // unchanged values are counted, not listed
}

TEST(ResultsDiff, JsonHasEveryComparisonWithItsVerdict) {
  const DiffReport diff = diffResults(
      runWith("base", {{"relmse", 0.02}, {"ssim", 0.9}}, test::noisyFrameTimes(1, 16, 8)),
      runWith("next", {{"relmse", kNaN}, {"ssim", 0.9}}, test::noisyFrameTimes(2, 16, 8)));
  const nlohmann::ordered_json j = diffJson(diff);
  EXPECT_EQ(j["base_run"], "base");
  EXPECT_EQ(j["new_run"], "next");
  EXPECT_EQ(j["regressions"], 1);
  ASSERT_EQ(j["metrics"].size(), 2u);
  EXPECT_EQ(j["metrics"][0]["new"], "nan");
  EXPECT_EQ(j["metrics"][0]["verdict"], "regressed");
  EXPECT_EQ(j["metrics"][1]["verdict"], "unchanged");
  ASSERT_EQ(j["timings"].size(), 1u);
  EXPECT_TRUE(j["timings"][0]["p_value"].is_number());
  EXPECT_EQ(j["timings"][0]["evidence"], "frames");
  EXPECT_TRUE(j["timings"][0]["detectable_change"].is_number());
  EXPECT_TRUE(j["timings"][0]["explanation"].is_string());
  // Parses back as strict JSON (non-finite numbers are strings).
  EXPECT_TRUE(nlohmann::json::parse(j.dump()).is_object());
}

}  // namespace
}  // namespace gib::results
