#include "reports/run_comparison.h"

#include "reports/html_text.h"
#include "reports/number_format.h"

#include <fmt/format.h>

namespace gib::reports {

namespace {

// Folds one value's verdict into the job's: a regression outweighs an unconfirmed change, which
// outweighs an improvement.
void fold(results::Verdict& overall, results::Verdict value) {
  if (value == results::Verdict::kRegressed || value == results::Verdict::kMissing)
    overall = results::Verdict::kRegressed;
  else if (value == results::Verdict::kUnconfirmed && overall != results::Verdict::kRegressed)
    overall = results::Verdict::kUnconfirmed;
  else if (value == results::Verdict::kImproved && overall == results::Verdict::kUnchanged)
    overall = results::Verdict::kImproved;
}

std::string spanOf(const std::string& text, std::optional<results::Verdict> verdict,
                   std::optional<double> relative_change) {
  return fmt::format("<span class=\"{}\">{}</span>{}", verdictClass(verdict), escapeHtml(text),
                     relative_change && *relative_change != 0
                         ? fmt::format(" <small>({})</small>", formatChange(*relative_change))
                         : std::string());
}

}  // namespace

RunComparison::RunComparison(const results::RunResults& results,
                             const std::optional<results::RunResults>& previous,
                             const std::vector<results::RunResults>& history) {
  if (!previous) return;
  previous_run_ = previous->run;
  diff_ = results::diffResults(*previous, results,
                               {results::timingHistoryOf(history, *previous, results)});
  for (const results::MetricChange& change : diff_->metrics) {
    JobComparison& job = jobs_[change.job];
    fold(job.overall, change.verdict);
    job.metrics.emplace(change.metric, change);
  }
  for (const results::TimingChange& change : diff_->timings) {
    JobComparison& job = jobs_[change.job];
    fold(job.overall, change.verdict);
    job.timing = change;
  }
  for (const results::JobPresence& presence : diff_->presence)
    if (presence.verdict == results::Verdict::kAdded)
      jobs_[presence.job].overall = results::Verdict::kAdded;
}

std::optional<JobComparison> RunComparison::job(const std::string& id) const {
  if (!diff_) return std::nullopt;
  const auto it = jobs_.find(id);
  return it == jobs_.end() ? JobComparison{} : it->second;
}

const char* verdictClass(std::optional<results::Verdict> verdict) {
  if (verdict == results::Verdict::kRegressed || verdict == results::Verdict::kMissing)
    return "verdict-regressed";
  if (verdict == results::Verdict::kImproved) return "verdict-improved";
  if (verdict == results::Verdict::kUnconfirmed) return "verdict-unconfirmed";
  return "verdict-unchanged";
}

std::string verdictSpan(const std::string& text, const results::MetricChange* change) {
  return change ? spanOf(text, change->verdict, change->relative_change)
                : spanOf(text, std::nullopt, std::nullopt);
}

std::string verdictSpan(const std::string& text,
                        const std::optional<results::TimingChange>& change) {
  return change ? spanOf(text, change->verdict, change->relative_change)
                : spanOf(text, std::nullopt, std::nullopt);
}

}  // namespace gib::reports
