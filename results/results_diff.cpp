#include "results/results_diff.h"

#include "metrics/distributions.h"
#include "metrics/metric_registry.h"
#include "results/json_number.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>
#include <unordered_map>

namespace gib::results {

namespace {

using json = nlohmann::ordered_json;

constexpr std::string_view kFullPrefix = "full:";

double relativeChange(double base, double next) {
  if (next == base || (std::isnan(base) && std::isnan(next))) return 0;
  if (base == 0) return std::copysign(std::numeric_limits<double>::infinity(), next - base);
  return (next - base) / std::abs(base);
}

// NaN is worse than any number; infinities are compared by direction (a PSNR of +inf is a
// perfect image, a relMSE of +inf a broken one), and a change to or from one is never noise.
Verdict judgeMetric(double base, double next, const Tolerance& tolerance, const std::string& name) {
  if (std::isnan(base) || std::isnan(next)) {
    if (std::isnan(base) && std::isnan(next)) return Verdict::kUnchanged;
    return std::isnan(next) ? Verdict::kRegressed : Verdict::kImproved;
  }
  if (base == next) return Verdict::kUnchanged;
  // A value that describes an error (how concentrated it is) has no better direction.
  if (const metrics::MetricValueInfo* info = metrics::findMetricValue(name);
      info && info->direction == metrics::MetricDirection::kDescriptive)
    return Verdict::kUnchanged;
  const double change = next - base;
  const double allowed = std::max(tolerance.absolute, tolerance.relative * std::abs(base));
  const bool finite = std::isfinite(base) && std::isfinite(next);
  if (finite && std::abs(change) <= allowed) return Verdict::kUnchanged;
  const bool better =
      metrics::distanceFromIdeal(name, next) < metrics::distanceFromIdeal(name, base);
  return better ? Verdict::kImproved : Verdict::kRegressed;
}

void diffValues(const std::string& job, const NamedValues& base, const NamedValues& next,
                std::string_view prefix, const Tolerances& tolerances,
                std::vector<MetricChange>& out) {
  for (const auto& [name, base_value] : base) {
    // (clang 14, the sanitizer build's compiler, cannot capture a structured binding.)
    auto it = std::find_if(next.begin(), next.end(),
                           [&name = name](const auto& v) { return v.first == name; });
    if (it == next.end()) continue;
    MetricChange change;
    change.job = job;
    change.metric = std::string(prefix) + name;
    change.base = base_value;
    change.next = it->second;
    change.absolute_change = change.next - change.base;
    change.relative_change = relativeChange(change.base, change.next);
    change.tolerance = tolerances.forMetric(name);
    change.verdict = judgeMetric(change.base, change.next, change.tolerance, name);
    out.push_back(change);
  }
}

template <typename Change>
std::size_t countVerdict(const std::vector<Change>& changes, Verdict verdict) {
  return std::size_t(std::count_if(changes.begin(), changes.end(),
                                   [&](const Change& c) { return c.verdict == verdict; }));
}

std::string formatPercent(double relative) {
  return std::isfinite(relative) ? fmt::format("{:+.1f}%", 100 * relative) : std::string("n/a");
}

std::string plural(std::size_t count, const char* noun) {
  return fmt::format("{} {}{}", count, noun, count == 1 ? "" : "s");
}

std::string formatMetricLine(const MetricChange& c) {
  return fmt::format("{:<11} {}  {}  {:.6g} -> {:.6g}  {}  (tolerance {:g}%, absolute {:g})",
                     verdictName(c.verdict), c.job, c.metric, c.base, c.next,
                     formatPercent(c.relative_change), 100 * c.tolerance.relative,
                     c.tolerance.absolute);
}

std::string formatTimingLine(const TimingChange& c) {
  return fmt::format("{:<11} {}  frame  {:.4g} ms -> {:.4g} ms  {}  (tolerance {:g}%; {})",
                     verdictName(c.verdict), c.job, c.base_median_ms, c.next_median_ms,
                     formatPercent(c.relative_change), 100 * c.tolerance.relative, c.explanation());
}

// The lines of one verdict: metrics, then timings, then jobs.
void appendLines(const DiffReport& diff, Verdict verdict, std::string& out) {
  for (const MetricChange& c : diff.metrics)
    if (c.verdict == verdict) out += formatMetricLine(c) + "\n";
  for (const TimingChange& c : diff.timings)
    if (c.verdict == verdict) out += formatTimingLine(c) + "\n";
  for (const JobPresence& p : diff.presence)
    if (p.verdict == verdict)
      out += fmt::format("{:<11} {}  ({})\n", verdictName(verdict), p.job,
                         verdict == Verdict::kMissing ? "in the base run, not in the new one"
                         : verdict == Verdict::kAdded ? "new in this run"
                                                      : "the new run ran part of its suite");
}

// Timings judged unchanged are counted, with the range of changes their evidence could have
// detected: "unchanged" is only as strong as the test behind it.
std::string unchangedTimingsLine(const DiffReport& diff) {
  std::vector<double> detectable;
  std::size_t by_history = 0, confirmed = 0;
  for (const TimingChange& c : diff.timings) {
    if (c.verdict != Verdict::kUnchanged) continue;
    detectable.push_back(c.detectable_change);
    by_history += c.evidence == TimingEvidence::kHistory;
    confirmed += c.evidence == TimingEvidence::kConfirmation;
  }
  if (detectable.empty()) return {};
  const auto [least, most] = std::minmax_element(detectable.begin(), detectable.end());
  const std::string range =
      *least == *most ? formatPercent(*least).substr(1) + " or more"
                      : formatPercent(*least).substr(1) + " to " + formatPercent(*most).substr(1);
  return fmt::format(
      "{:<11} {} timing{} within tolerance ({} by history, {} confirmed A/B, {} within the runs "
      "only); their evidence detects changes of {}\n",
      "unchanged", detectable.size(), detectable.size() == 1 ? "" : "s", by_history, confirmed,
      detectable.size() - by_history - confirmed, range);
}

json toleranceJson(const Tolerance& t) {
  return {{"absolute", numberToJson(t.absolute)}, {"relative", numberToJson(t.relative)}};
}

}  // namespace

std::size_t DiffReport::regressions() const {
  std::size_t strict = 0;
  if (strict_timing)
    for (const TimingChange& c : timings)
      strict += c.verdict == Verdict::kUnconfirmed && c.relative_change > 0;
  return countVerdict(metrics, Verdict::kRegressed) + countVerdict(timings, Verdict::kRegressed) +
         countVerdict(presence, Verdict::kMissing) + strict;
}

std::size_t DiffReport::unconfirmed() const {
  return countVerdict(timings, Verdict::kUnconfirmed);
}

std::size_t DiffReport::improvements() const {
  return countVerdict(metrics, Verdict::kImproved) + countVerdict(timings, Verdict::kImproved);
}

DiffReport diffResults(const RunResults& base, const RunResults& next, const DiffOptions& options) {
  DiffReport diff;
  diff.base_run = base.run.id;
  diff.next_run = next.run.id;
  diff.strict_timing = options.strict_timing;
  // The timed jobs of both runs, judged once their number (the Šidák family) is known.
  std::vector<std::pair<const JobResult*, const JobResult*>> timed;
  // Jobs by id: RunResults::findJob is a linear search, and nightly runs have a thousand jobs.
  std::unordered_map<std::string_view, const JobResult*> next_jobs, base_jobs;
  for (const JobResult& job : next.jobs) next_jobs.emplace(job.id, &job);
  for (const JobResult& job : base.jobs) base_jobs.emplace(job.id, &job);
  for (const JobResult& base_job : base.jobs) {
    auto found = next_jobs.find(base_job.id);
    const JobResult* next_job = found == next_jobs.end() ? nullptr : found->second;
    if (!next_job) {
      diff.presence.push_back(
          {base_job.id, next.run.complete ? Verdict::kMissing : Verdict::kNotRun});
      continue;
    }
    diffValues(base_job.id, base_job.metrics, next_job->metrics, "", next.tolerances, diff.metrics);
    // "full:ssim" is judged like "ssim": same tolerance, same direction.
    diffValues(base_job.id, base_job.metrics_full, next_job->metrics_full, kFullPrefix,
               next.tolerances, diff.metrics);
    if (base_job.runMedianMs() && next_job->runMedianMs()) timed.emplace_back(&base_job, next_job);
  }
  diff.timing_significance = next.tolerances.timing.significance;
  diff.timing_comparison_significance =
      timed.empty() ? diff.timing_significance
                    : metrics::sidakSignificance(diff.timing_significance, double(timed.size()));
  static const std::vector<double> kNoHistory;
  for (const auto& [base_job, next_job] : timed) {
    const auto found = options.history.find(next_job->id);
    const std::vector<double>& history =
        found == options.history.end() ? kNoHistory : found->second;
    diff.timings.push_back(judgeTiming(*base_job, *next_job, history, next.tolerances.timing,
                                       diff.timing_comparison_significance));
  }
  for (const JobResult& next_job : next.jobs)
    if (!base_jobs.contains(next_job.id)) diff.presence.push_back({next_job.id, Verdict::kAdded});
  return diff;
}

std::string formatDiff(const DiffReport& diff, bool verbose) {
  std::string out = fmt::format("base {}\nnew  {}\n", diff.base_run, diff.next_run);
  for (Verdict verdict : {Verdict::kRegressed, Verdict::kMissing, Verdict::kImproved,
                          Verdict::kUnconfirmed, Verdict::kAdded})
    appendLines(diff, verdict, out);
  if (verbose)
    for (const TimingChange& c : diff.timings)
      if (c.verdict == Verdict::kUnchanged) out += formatTimingLine(c) + "\n";
  out += unchangedTimingsLine(diff);
  const std::size_t unchanged = countVerdict(diff.metrics, Verdict::kUnchanged) +
                                countVerdict(diff.timings, Verdict::kUnchanged);
  out += fmt::format("{}, {}, {} unconfirmed{}, {} unchanged, {} added",
                     plural(diff.regressions(), "regression"),
                     plural(diff.improvements(), "improvement"), diff.unconfirmed(),
                     diff.strict_timing ? " (slowdowns counted: --strict-timing)" : "", unchanged,
                     countVerdict(diff.presence, Verdict::kAdded));
  // Jobs a partial run left out are counted, not listed: a bisect step may leave out hundreds.
  if (const std::size_t not_run = countVerdict(diff.presence, Verdict::kNotRun))
    out += fmt::format(", {} not run (the new run ran part of its suite)", not_run);
  out += fmt::format("; timing false-regression rate at most {:g} per diff\n",
                     diff.timing_significance);
  return out;
}

json diffJson(const DiffReport& diff) {
  json metrics = json::array();
  for (const MetricChange& c : diff.metrics)
    metrics.push_back({{"job", c.job},
                       {"metric", c.metric},
                       {"base", numberToJson(c.base)},
                       {"new", numberToJson(c.next)},
                       {"absolute_change", numberToJson(c.absolute_change)},
                       {"relative_change", numberToJson(c.relative_change)},
                       {"tolerance", toleranceJson(c.tolerance)},
                       {"verdict", verdictName(c.verdict)}});
  json timings = json::array();
  for (const TimingChange& c : diff.timings)
    timings.push_back({{"job", c.job},
                       {"base_median_ms", numberToJson(c.base_median_ms)},
                       {"new_median_ms", numberToJson(c.next_median_ms)},
                       {"relative_change", numberToJson(c.relative_change)},
                       {"evidence", evidenceName(c.evidence)},
                       {"base_samples", c.base_samples},
                       {"new_samples", c.next_samples},
                       {"history_runs", c.history_runs},
                       {"run_to_run_spread", numberToJson(c.run_to_run_spread)},
                       {"p_value", numberToJson(c.p_value)},
                       {"significance", numberToJson(c.significance)},
                       {"detectable_change", numberToJson(c.detectable_change)},
                       {"pairs_base_ms", c.pairs_base_ms},
                       {"pairs_new_ms", c.pairs_next_ms},
                       {"tolerance",
                        {{"relative", numberToJson(c.tolerance.relative)},
                         {"significance", numberToJson(c.tolerance.significance)}}},
                       {"verdict", verdictName(c.verdict)},
                       {"explanation", c.explanation()}});
  json jobs = json::array();
  for (const JobPresence& p : diff.presence)
    jobs.push_back({{"job", p.job}, {"verdict", verdictName(p.verdict)}});
  return {{"base_run", diff.base_run},
          {"new_run", diff.next_run},
          {"regressions", diff.regressions()},
          {"improvements", diff.improvements()},
          {"unconfirmed", diff.unconfirmed()},
          {"strict_timing", diff.strict_timing},
          {"timing_significance", numberToJson(diff.timing_significance)},
          {"timing_comparison_significance", numberToJson(diff.timing_comparison_significance)},
          {"metrics", std::move(metrics)},
          {"timings", std::move(timings)},
          {"jobs", std::move(jobs)}};
}

}  // namespace gib::results
