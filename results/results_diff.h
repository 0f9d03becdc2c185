// `gibench diff`: what changed between two runs, and whether it is a regression or noise.
// Metrics are judged by the new run's tolerances (results/results.h: Tolerance): deterministic
// renders make every metric exact, so a change beyond tolerance is real. Frame times are judged
// by results/timing_verdict.h: the tolerance and the best evidence of noise at hand.
#pragma once

#include "results/results.h"
#include "results/timing_history.h"
#include "results/timing_verdict.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gib::results {

struct MetricChange {
  std::string job;
  std::string metric;  // metric value name; "full:<name>" for the full-reference values
  double base = 0, next = 0;
  double absolute_change = 0;  // next − base
  double relative_change = 0;  // (next − base) / |base|; 0 when base is 0 and next is 0
  Tolerance tolerance;
  Verdict verdict = Verdict::kUnchanged;
};

struct JobPresence {
  std::string job;
  Verdict verdict;  // kMissing, kAdded or kNotRun
};

struct DiffOptions {
  // Per-run medians of comparable earlier runs, by job id (results/timing_history.h); empty:
  // timings are judged within the two runs alone.
  TimingHistory history;
  // Count an unconfirmed slowdown as a regression (a bisect that must not miss one).
  bool strict_timing = false;
};

struct DiffReport {
  std::string base_run, next_run;  // run ids
  std::vector<MetricChange> metrics;
  std::vector<TimingChange> timings;
  std::vector<JobPresence> presence;
  bool strict_timing = false;
  // The suite's timing significance and the per-comparison one after the Šidák correction over
  // `timings`: the chance that the diff calls a false timing regression is at most the first.
  double timing_significance = 0, timing_comparison_significance = 0;
  std::size_t regressions() const;  // metrics, timings, missing jobs (and unconfirmed if strict)
  std::size_t improvements() const;
  std::size_t unconfirmed() const;
};

DiffReport diffResults(const RunResults& base, const RunResults& next,
                       const DiffOptions& options = {});

// For people: the regressions and improvements (unchanged values counted, not listed), one line
// per change, and a summary line.
std::string formatDiff(const DiffReport& diff, bool verbose = false);
nlohmann::ordered_json diffJson(const DiffReport& diff);

}  // namespace gib::results
