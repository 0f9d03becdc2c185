// How `gibench diff` judges a change of a job's frame time: by the best evidence at hand, each
// with a stated false-positive rate, and with the smallest change the evidence could have seen,
// so that "unchanged" never hides a test too weak to tell.
//
// Evidence, best first:
//   kConfirmation  interleaved A/B runs of the base and the new build on this machine (`diff
//                  --confirm`): the signed-rank test of their log ratios, pair by pair, cancels
//                  the machine's drift.
//   kHistory       the run-to-run spread of the job's median over comparable earlier runs (five
//                  or more, results/timing_history.h): a change is real when it lies outside it.
//   kRepeats,      only the noise within the two runs (their repeats, else their frames): two
//   kFrames        runs minutes apart differ by more than that, so a change they find significant
//                  is `unconfirmed` (shown, not a regression unless --strict-timing).
// A change regresses only when it exceeds the suite's timing tolerance *and* the evidence says it
// is not noise at the per-comparison significance (the suite's, Šidák-corrected over the diff's
// timing comparisons, so that a whole diff calls a false regression at most that often).
#pragma once

#include "results/results.h"

#include <cstddef>
#include <string>
#include <vector>

namespace gib::results {

enum class Verdict {
  kUnchanged,  // within tolerance (or bit-identical)
  kImproved,   // beyond tolerance, for the better
  kRegressed,  // beyond tolerance, for the worse (or became non-finite)
  kMissing,    // in the base run, not in the new one: counted as a regression
  kAdded,      // in the new run only: reported, not judged
  // In the base run, not in a new run that ran only part of its suite (`gibench run --only`,
  // RunInfo::complete false, as a bisect step does): reported, not judged.
  kNotRun,
  // A timing beyond tolerance that the evidence cannot tell from noise (or can only by noise
  // within the runs): reported with what would settle it, not counted unless --strict-timing.
  kUnconfirmed,
};
const char* verdictName(Verdict verdict);  // "unchanged", "improved", …

enum class TimingEvidence { kConfirmation, kHistory, kRepeats, kFrames };
const char* evidenceName(TimingEvidence evidence);  // "interleaved A/B", "history", …

// The fewest comparable earlier runs whose spread the history rule relies on.
inline constexpr std::size_t kMinHistoryRuns = 5;

struct TimingChange {
  std::string job;
  // Per-run medians (JobResult::runMedianMs), or the medians of the A/B runs when confirmed.
  double base_median_ms = 0, next_median_ms = 0;
  double relative_change = 0;  // next / base − 1; the A/B estimate when confirmed
  TimingEvidence evidence = TimingEvidence::kFrames;
  std::size_t base_samples = 0, next_samples = 0;  // frames, repeats or A/B runs of each
  std::size_t history_runs = 0;                    // comparable earlier runs (kHistory)
  double run_to_run_spread = 0;  // relative, one standard deviation of ln(median) (kHistory)
  double p_value = 1;            // two-sided, of "no change", by the evidence's test
  double significance = 0;       // per comparison (the tolerance's, Šidák-corrected)
  // The smallest change (relative) the evidence detects with probability 95%: a change below it
  // may hide in the noise even when the verdict is "unchanged".
  double detectable_change = 0;
  std::vector<double> pairs_base_ms, pairs_next_ms;  // the A/B runs' medians (kConfirmation)
  TimingTolerance tolerance;
  Verdict verdict = Verdict::kUnchanged;

  // One line for people: the evidence, its numbers and what the verdict rests on.
  std::string explanation() const;
};

// Judges `base` → `next` (both timed) with the job's `history` (per-run medians of comparable
// earlier runs, possibly empty) at per-comparison `significance`.
TimingChange judgeTiming(const JobResult& base, const JobResult& next,
                         const std::vector<double>& history, const TimingTolerance& tolerance,
                         double significance);

// Judges again from interleaved A/B runs (their per-run medians, a_i run right before b_i).
void confirmTiming(TimingChange& change, std::vector<double> a_ms, std::vector<double> b_ms);

// Whether interleaved A/B runs could change the verdict: every timing but one the history shows
// unchanged with power to spare (its detectable change within the tolerance). A change the runs
// alone call small proves nothing: drift between two runs can hide a real slowdown as well as
// fake one.
bool worthConfirming(const TimingChange& change);

}  // namespace gib::results
