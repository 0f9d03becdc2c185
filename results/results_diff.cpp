#include "results/results_diff.h"

#include "metrics/metric_registry.h"
#include "metrics/timing_statistics.h"
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
    auto it =
        std::find_if(next.begin(), next.end(), [&](const auto& v) { return v.first == name; });
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

// Both conditions (results/results.h, TimingTolerance): a change large enough to matter, and
// one the rank test says is not noise.
TimingChange diffTiming(const std::string& job, const std::vector<double>& base,
                        const std::vector<double>& next, const TimingTolerance& tolerance) {
  TimingChange change;
  change.job = job;
  change.base_median_ms = metrics::quantile(base, 0.5);
  change.next_median_ms = metrics::quantile(next, 0.5);
  change.relative_change = relativeChange(change.base_median_ms, change.next_median_ms);
  change.p_value = metrics::mannWhitneyU(base, next).p_value;
  change.tolerance = tolerance;
  const bool significant = change.p_value < tolerance.significance;
  if (significant && change.relative_change > tolerance.relative)
    change.verdict = Verdict::kRegressed;
  else if (significant && change.relative_change < -tolerance.relative)
    change.verdict = Verdict::kImproved;
  return change;
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
  return fmt::format("{:<10} {}  {}  {:.6g} -> {:.6g}  {}  (tolerance {:g}%, absolute {:g})",
                     verdictName(c.verdict), c.job, c.metric, c.base, c.next,
                     formatPercent(c.relative_change), 100 * c.tolerance.relative,
                     c.tolerance.absolute);
}

std::string formatTimingLine(const TimingChange& c) {
  return fmt::format(
      "{:<10} {}  frame  {:.4g} ms -> {:.4g} ms  {}  (tolerance {:g}%, p = {:.2g} vs {:g})",
      verdictName(c.verdict), c.job, c.base_median_ms, c.next_median_ms,
      formatPercent(c.relative_change), 100 * c.tolerance.relative, c.p_value,
      c.tolerance.significance);
}

// The lines of one verdict: metrics, then timings, then jobs.
void appendLines(const DiffReport& diff, Verdict verdict, std::string& out) {
  for (const MetricChange& c : diff.metrics)
    if (c.verdict == verdict) out += formatMetricLine(c) + "\n";
  for (const TimingChange& c : diff.timings)
    if (c.verdict == verdict) out += formatTimingLine(c) + "\n";
  for (const JobPresence& p : diff.presence)
    if (p.verdict == verdict)
      out += fmt::format("{:<10} {}  ({})\n", verdictName(verdict), p.job,
                         verdict == Verdict::kMissing ? "in the base run, not in the new one"
                         : verdict == Verdict::kAdded ? "new in this run"
                                                      : "the new run ran part of its suite");
}

json toleranceJson(const Tolerance& t) {
  return {{"absolute", numberToJson(t.absolute)}, {"relative", numberToJson(t.relative)}};
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
  }
  return "unknown";
}

std::size_t DiffReport::regressions() const {
  return countVerdict(metrics, Verdict::kRegressed) + countVerdict(timings, Verdict::kRegressed) +
         countVerdict(presence, Verdict::kMissing);
}

std::size_t DiffReport::improvements() const {
  return countVerdict(metrics, Verdict::kImproved) + countVerdict(timings, Verdict::kImproved);
}

DiffReport diffResults(const RunResults& base, const RunResults& next) {
  DiffReport diff;
  diff.base_run = base.run.id;
  diff.next_run = next.run.id;
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
    const std::vector<double> base_frames = base_job.frameSamplesMs();
    const std::vector<double> next_frames = next_job->frameSamplesMs();
    if (!base_frames.empty() && !next_frames.empty())
      diff.timings.push_back(
          diffTiming(base_job.id, base_frames, next_frames, next.tolerances.timing));
  }
  for (const JobResult& next_job : next.jobs)
    if (!base_jobs.contains(next_job.id)) diff.presence.push_back({next_job.id, Verdict::kAdded});
  return diff;
}

std::string formatDiff(const DiffReport& diff) {
  std::string out = fmt::format("base {}\nnew  {}\n", diff.base_run, diff.next_run);
  for (Verdict verdict :
       {Verdict::kRegressed, Verdict::kMissing, Verdict::kImproved, Verdict::kAdded})
    appendLines(diff, verdict, out);
  const std::size_t unchanged = countVerdict(diff.metrics, Verdict::kUnchanged) +
                                countVerdict(diff.timings, Verdict::kUnchanged);
  out += fmt::format("{}, {}, {} unchanged, {} added", plural(diff.regressions(), "regression"),
                     plural(diff.improvements(), "improvement"), unchanged,
                     countVerdict(diff.presence, Verdict::kAdded));
  // Jobs a partial run left out are counted, not listed: a bisect step may leave out hundreds.
  if (const std::size_t not_run = countVerdict(diff.presence, Verdict::kNotRun))
    out += fmt::format(", {} not run (the new run ran part of its suite)", not_run);
  out += "\n";
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
                       {"p_value", numberToJson(c.p_value)},
                       {"tolerance",
                        {{"relative", numberToJson(c.tolerance.relative)},
                         {"significance", numberToJson(c.tolerance.significance)}}},
                       {"verdict", verdictName(c.verdict)}});
  json jobs = json::array();
  for (const JobPresence& p : diff.presence)
    jobs.push_back({{"job", p.job}, {"verdict", verdictName(p.verdict)}});
  return {{"base_run", diff.base_run},
          {"new_run", diff.next_run},
          {"regressions", diff.regressions()},
          {"improvements", diff.improvements()},
          {"metrics", std::move(metrics)},
          {"timings", std::move(timings)},
          {"jobs", std::move(jobs)}};
}

}  // namespace gib::results
