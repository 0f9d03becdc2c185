// `gibench diff`: what changed between two runs, and whether it is a regression or noise.
// Metrics are judged by the new run's tolerances (results/results.h: Tolerance), frame times by
// the relative threshold and the Mann–Whitney U test of the per-frame samples (TimingTolerance).
#pragma once

#include "results/results.h"

#include <nlohmann/json.hpp>

#include <optional>
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
};
const char* verdictName(Verdict verdict);  // "unchanged", "improved", …

struct MetricChange {
  std::string job;
  std::string metric;  // metric value name; "full:<name>" for the full-reference values
  double base = 0, next = 0;
  double absolute_change = 0;  // next − base
  double relative_change = 0;  // (next − base) / |base|; 0 when base is 0 and next is 0
  Tolerance tolerance;
  Verdict verdict = Verdict::kUnchanged;
};

struct TimingChange {
  std::string job;
  double base_median_ms = 0, next_median_ms = 0;
  double relative_change = 0;
  double p_value = 1;  // Mann–Whitney U, two-sided; 1 when either side has no samples
  TimingTolerance tolerance;
  Verdict verdict = Verdict::kUnchanged;
};

struct JobPresence {
  std::string job;
  Verdict verdict;  // kMissing, kAdded or kNotRun
};

struct DiffReport {
  std::string base_run, next_run;  // run ids
  std::vector<MetricChange> metrics;
  std::vector<TimingChange> timings;
  std::vector<JobPresence> presence;
  std::size_t regressions() const;
  std::size_t improvements() const;
};

DiffReport diffResults(const RunResults& base, const RunResults& next);

// For people: the regressions and improvements (unchanged values counted, not listed), one line
// per change, and a summary line.
std::string formatDiff(const DiffReport& diff);
nlohmann::ordered_json diffJson(const DiffReport& diff);

}  // namespace gib::results
