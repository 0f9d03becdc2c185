// What the report colours: the diff of a run against the suite's previous run
// (reports/results_diff.h), arranged per job so that the index matrix and the job pages can look
// up the verdict of a value.
#pragma once

#include "results/results.h"
#include "results/results_diff.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gib::reports {

struct JobComparison {
  // kRegressed when any value of the job regressed, else kImproved when any improved, else
  // kUnchanged; kAdded when the previous run did not have the job.
  results::Verdict overall = results::Verdict::kUnchanged;
  std::map<std::string, results::MetricChange>
      metrics;  // by results::MetricChange::metric ("relmse", "full:…")
  std::optional<results::TimingChange> timing;

  const results::MetricChange* findMetric(const std::string& name) const {
    const auto it = metrics.find(name);
    return it == metrics.end() ? nullptr : &it->second;
  }
};

class RunComparison {
 public:
  // No previous run: nothing is compared and every lookup answers "no comparison". `history`
  // (the suite's recent runs) gives timings their run-to-run spread (results/timing_history.h).
  RunComparison(const results::RunResults& results,
                const std::optional<results::RunResults>& previous,
                const std::vector<results::RunResults>& history = {});

  bool hasPrevious() const { return diff_.has_value(); }
  const std::optional<results::RunInfo>& previousRun() const { return previous_run_; }
  const std::optional<results::DiffReport>& diff() const { return diff_; }

  // nullopt without a previous run.
  std::optional<JobComparison> job(const std::string& id) const;

 private:
  std::optional<results::RunInfo> previous_run_;
  std::optional<results::DiffReport> diff_;
  std::map<std::string, JobComparison> jobs_;
};

// The CSS class of a verdict in the report: "verdict-regressed", "verdict-improved",
// "verdict-unchanged" (also for added and for no comparison).
const char* verdictClass(std::optional<results::Verdict> verdict);

// `text` (escaped here) in a span of the change's verdict class, followed by the relative change
// in small print when it is not zero: `<span class="verdict-regressed">0.013</span>
// <small>(+12.5%)</small>`. No change (null, nullopt): a neutral span.
std::string verdictSpan(const std::string& text, const results::MetricChange* change);
std::string verdictSpan(const std::string& text,
                        const std::optional<results::TimingChange>& change);

}  // namespace gib::reports
