#include "results/timing_verdict.h"

#include "metrics/timing_statistics.h"

#include <fmt/format.h>

#include <cmath>

namespace gib::results {

namespace {

std::string percent(double relative) {
  return std::isfinite(relative) ? fmt::format("{:.1f}%", 100 * relative) : std::string("∞");
}

// The verdict of an estimated change by a test of it: beyond tolerance and not noise by strong
// evidence is a regression or an improvement; beyond tolerance otherwise is unconfirmed.
Verdict decide(const TimingChange& c) {
  if (std::abs(c.relative_change) <= c.tolerance.relative) return Verdict::kUnchanged;
  const bool strong =
      c.evidence == TimingEvidence::kConfirmation || c.evidence == TimingEvidence::kHistory;
  if (strong && c.p_value < c.significance)
    return c.relative_change > 0 ? Verdict::kRegressed : Verdict::kImproved;
  return Verdict::kUnconfirmed;
}

void apply(TimingChange& change, const metrics::TimingTest& test) {
  change.p_value = test.p_value;
  change.detectable_change = test.detectable_change;
  change.verdict = decide(change);
}

}  // namespace

const char* verdictName(Verdict verdict) {
  switch (verdict) {
    case Verdict::kUnchanged:
      return "unchanged";
    case Verdict::kImproved:
      return "improved";
    case Verdict::kRegressed:
      return "regressed";
    case Verdict::kMissing:
      return "missing";
    case Verdict::kAdded:
      return "added";
    case Verdict::kNotRun:
      return "not run";
    case Verdict::kUnconfirmed:
      return "unconfirmed";
  }
  return "unknown";
}

const char* evidenceName(TimingEvidence evidence) {
  switch (evidence) {
    case TimingEvidence::kConfirmation:
      return "interleaved A/B";
    case TimingEvidence::kHistory:
      return "history";
    case TimingEvidence::kRepeats:
      return "repeats";
    case TimingEvidence::kFrames:
      return "frames";
  }
  return "unknown";
}

TimingChange judgeTiming(const JobResult& base, const JobResult& next,
                         const std::vector<double>& history, const TimingTolerance& tolerance,
                         double significance) {
  TimingChange change;
  change.job = next.id;
  change.tolerance = tolerance;
  change.significance = significance;
  change.base_median_ms = base.runMedianMs().value_or(0);
  change.next_median_ms = next.runMedianMs().value_or(0);
  change.relative_change = change.next_median_ms / change.base_median_ms - 1.0;
  const std::vector<double> base_repeats = base.repeatMediansMs();
  const std::vector<double> next_repeats = next.repeatMediansMs();
  if (history.size() >= kMinHistoryRuns) {
    change.evidence = TimingEvidence::kHistory;
    change.history_runs = history.size();
    change.base_samples = base_repeats.size();
    change.next_samples = next_repeats.size();
    const metrics::TimingTest test = metrics::testAgainstRunToRunSpread(
        change.base_median_ms, change.next_median_ms, history, significance);
    change.run_to_run_spread = metrics::runToRunSpread(history);
    apply(change, test);
    return change;
  }
  const bool repeated = base_repeats.size() >= 2 && next_repeats.size() >= 2;
  const std::vector<double> a = repeated ? base_repeats : base.frameSamplesMs();
  const std::vector<double> b = repeated ? next_repeats : next.frameSamplesMs();
  change.evidence = repeated ? TimingEvidence::kRepeats : TimingEvidence::kFrames;
  change.base_samples = a.size();
  change.next_samples = b.size();
  if (a.size() < 2 || b.size() < 2) {
    change.verdict = decide(change);  // nothing to test with: at best unconfirmed
    return change;
  }
  apply(change, metrics::testWithinRuns(a, b, significance));
  return change;
}

void confirmTiming(TimingChange& change, std::vector<double> a_ms, std::vector<double> b_ms) {
  const metrics::TimingTest test = metrics::testInterleavedPairs(a_ms, b_ms, change.significance);
  change.evidence = TimingEvidence::kConfirmation;
  change.base_median_ms = metrics::quantile(a_ms, 0.5);
  change.next_median_ms = metrics::quantile(b_ms, 0.5);
  change.relative_change = test.ratio - 1.0;
  change.base_samples = a_ms.size();
  change.next_samples = b_ms.size();
  change.pairs_base_ms = std::move(a_ms);
  change.pairs_next_ms = std::move(b_ms);
  apply(change, test);
}

bool worthConfirming(const TimingChange& change) {
  return !(change.verdict == Verdict::kUnchanged && change.evidence == TimingEvidence::kHistory &&
           change.detectable_change <= change.tolerance.relative);
}

std::string TimingChange::explanation() const {
  std::string evidence_text;
  switch (evidence) {
    case TimingEvidence::kConfirmation:
      evidence_text = fmt::format("{} interleaved A/B runs of each build", base_samples);
      break;
    case TimingEvidence::kHistory:
      evidence_text = fmt::format("history of {} comparable runs, run-to-run spread ±{}",
                                  history_runs, percent(run_to_run_spread));
      break;
    case TimingEvidence::kRepeats:
    case TimingEvidence::kFrames:
      evidence_text = fmt::format(
          "{} + {} {} within the two runs only (fewer than {} comparable runs in the history)",
          base_samples, next_samples, evidenceName(evidence), kMinHistoryRuns);
      break;
  }
  std::string text = fmt::format("{}; p = {:.2g} against significance {:.2g}", evidence_text,
                                 p_value, significance);
  if (detectable_change > 0)
    text += fmt::format("; detects changes of {} or more", percent(detectable_change));
  // A change the test sees but the tolerance allows is named as such: "unchanged" means
  // "within the tolerance", not "the same".
  if (verdict == Verdict::kUnchanged && p_value < significance)
    text += fmt::format("; a real change, within the {} tolerance", percent(tolerance.relative));
  if (verdict == Verdict::kUnconfirmed)
    text += evidence == TimingEvidence::kConfirmation || evidence == TimingEvidence::kHistory
                ? "; not told from noise"
                : "; `gibench diff --confirm` settles it";
  return text;
}

}  // namespace gib::results
