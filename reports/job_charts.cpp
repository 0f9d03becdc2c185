#include "reports/job_charts.h"

#include "reports/html_text.h"
#include "reports/number_format.h"
#include "reports/report_labels.h"
#include "reports/report_page.h"
#include "reports/svg_charts.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <functional>
#include <limits>

namespace gib::reports {

namespace {

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

std::string timingsIntro(const metrics::PassTimings& timings,
                         const std::optional<JobComparison>& compared) {
  std::string intro = fmt::format("<p>{}; {} warm-up and {} measured frames.",
                                  escapeHtml(timings.clockDescription()), timings.warmup_frames,
                                  timings.measured_frames);
  const double frame = timings.root().reported.median;
  if (std::isfinite(frame))
    intro += fmt::format(" Median frame {} ms", escapeHtml(formatNumber(frame)));
  if (const std::optional<double> fps = timings.frameRateFps())
    intro += fmt::format(" ({} fps)", formatNumber(*fps, 3));
  if (compared && compared->timing) {
    const results::TimingChange& t = *compared->timing;
    intro += fmt::format("; previous run {} ms, now {}: {} ({})", formatNumber(t.base_median_ms),
                         verdictSpan(formatNumber(t.next_median_ms) + " ms", compared->timing),
                         results::verdictName(t.verdict), escapeHtml(t.explanation()));
  }
  return intro + ".</p>\n";
}

// `unit`: what one sample times, "frame" or "iteration".
std::string passTable(const metrics::PassTimings& timings, std::string_view unit) {
  HtmlTable table({{"pass"},
                   {"median ms", true},
                   {"first quartile", true},
                   {"third quartile", true},
                   {fmt::format("share of {}", unit), true},
                   {fmt::format("calls per {}", unit), true},
                   {fmt::format("GPU commands per {}", unit), true}});
  for (const metrics::PassTiming& pass : timings.passes)
    table.addRow({fmt::format("<span style=\"padding-left:{}em\">{}</span>",
                              1.2 * std::max(0, pass.depth), escapeHtml(pass.name)),
                  formatNumber(pass.reported.median), formatNumber(pass.reported.first_quartile),
                  formatNumber(pass.reported.third_quartile), formatShare(pass.share),
                  formatNumber(pass.calls_per_frame, 3),
                  pass.gpu_commands_per_frame ? formatNumber(*pass.gpu_commands_per_frame, 4)
                                              : std::string("—")});
  return table.html();
}

std::vector<PassBar> passBars(const metrics::PassTimings& timings) {
  std::vector<PassBar> bars;
  for (const metrics::PassTiming& pass : timings.passes)
    bars.push_back({pass.name, pass.depth, pass.reported.median, pass.reported.first_quartile,
                    pass.reported.third_quartile});
  return bars;
}

// A job run several times: each run's median, the one shown below being the median of them.
std::string repeatsText(const results::JobResult& job) {
  if (job.repeats.size() < 2) return {};
  std::vector<std::string> medians;
  for (double median : job.repeatMediansMs()) medians.push_back(formatNumber(median));
  return fmt::format(
      "<p>{} runs of the job, each with a fresh GL context and interleaved with the other jobs' "
      "runs; their median frame times (ms): {}. The table shows the run of the median.</p>\n",
      job.repeats.size(), escapeHtml(fmt::format("{}", fmt::join(medians, ", "))));
}

std::string conditionsParagraph(const results::RunConditions& conditions) {
  return fmt::format("<p class=\"muted\">Machine around the job: {}.</p>\n",
                     escapeHtml(conditionsText(conditions)));
}

std::string phasesTable(const results::JobResult& job) {
  if (job.upload_ms == 0 && job.prepare_ms == 0 && job.iterate_ms == 0 && job.iterations == 0)
    return {};
  HtmlTable table({{"phase"}, {"ms", true}});
  table.addRow({"upload (scene to the GPU)", formatNumber(job.upload_ms)});
  table.addRow({"prepare (precomputation)", formatNumber(job.prepare_ms)});
  table.addRow(
      {fmt::format("iterate ({} iteration{})", job.iterations, job.iterations == 1 ? "" : "s"),
       formatNumber(job.iterate_ms)});
  return "<h3>Before the frames</h3>\n" + table.html();
}

// The metric the convergence plot shows: the fitted one, else the primary metric, else the first
// the points carry.
std::string convergenceMetric(const results::Convergence& convergence, const std::string& primary) {
  if (!convergence.fit_metric.empty()) return convergence.fit_metric;
  const results::NamedValues& first = convergence.points.front().metrics;
  for (const auto& [name, value] : first)
    if (name == primary) return primary;
  return first.empty() ? primary : first.front().first;
}

double valueOf(const results::NamedValues& values, const std::string& name) {
  for (const auto& [key, value] : values)
    if (key == name) return value;
  return kNoValue;
}

// One run's value of a job, for a trend; NaN when the run lacks the job or the value.
using JobValue = std::function<std::optional<double>(const results::JobResult&)>;

std::vector<TrendPoint> trendOf(const std::vector<const results::RunResults*>& runs,
                                const std::string& id, const JobValue& value) {
  std::vector<TrendPoint> points;
  for (const results::RunResults* run : runs) {
    const results::JobResult* job = run->findJob(id);
    const std::optional<double> v = job ? value(*job) : std::nullopt;
    points.push_back({shortCommit(run->run), v.value_or(kNoValue)});
  }
  return points;
}

bool anyFinite(const std::vector<TrendPoint>& points) {
  for (const TrendPoint& p : points)
    if (std::isfinite(p.value)) return true;
  return false;
}

}  // namespace

std::string timingsSection(const results::JobResult& job,
                           const std::optional<JobComparison>& compared) {
  const std::string phases = phasesTable(job);
  if (!job.timings)
    return phases.empty() ? std::string() : htmlSection("timings", "Timings", phases);
  return htmlSection("timings", "Timings",
                     timingsIntro(*job.timings, compared) + repeatsText(job) +
                         conditionsParagraph(job.conditions) + "<div class=\"charts\">\n" +
                         passTable(*job.timings, "frame") +
                         passTimingChart(passBars(*job.timings)) + "\n</div>\n" + phases);
}

std::string iterationTimingsSection(const results::JobResult& job) {
  if (!job.iteration_timings) return {};
  const metrics::PassTimings& timings = *job.iteration_timings;
  const std::string intro =
      fmt::format("<p>{}; {} iterations, each timed as one unit. Median iteration {} ms.</p>\n",
                  escapeHtml(timings.clockDescription()), timings.measured_frames,
                  escapeHtml(formatNumber(timings.root().reported.median)));
  return htmlSection("iteration-timings", "Time per iteration",
                     intro + "<div class=\"charts\">\n" + passTable(timings, "iteration") +
                         passTimingChart(passBars(timings), "iteration") + "\n</div>\n");
}

std::string convergenceSection(const results::JobResult& job, const std::string& primary_metric) {
  if (!job.convergence || job.convergence->points.empty()) return {};
  const results::Convergence& c = *job.convergence;
  const std::string metric = convergenceMetric(c, primary_metric);
  LogLogPlot plot{fmt::format("Convergence of {}", metric), c.x_label, metric, {}, std::nullopt};
  HtmlTable table({{c.x_label}, {metric, true}, {"seconds", true}});
  for (const results::Convergence::Point& point : c.points) {
    const double value = valueOf(point.metrics, metric);
    plot.points.emplace_back(point.x, value);
    table.addRow({formatNumber(point.x), formatNumber(value),
                  point.seconds > 0 ? formatNumber(point.seconds) : std::string()});
  }
  std::string fit = "<p class=\"note\">No fit: fewer than two usable points.</p>\n";
  if (!c.fit_metric.empty()) {
    plot.fit = FittedSlope{c.fit_slope, c.fit_slope_ci95};
    fit = fmt::format(
        "<p>Least-squares slope of log {} against log {}: <strong>{}</strong>{} (Monte Carlo "
        "noise alone falls with slope −0.5 for RMSE, −1 for MSE and relMSE).</p>\n",
        escapeHtml(metric), escapeHtml(c.x_label),
        escapeHtml(withMinusSign(formatNumber(c.fit_slope, 3))),
        std::isfinite(c.fit_slope_ci95)
            ? fmt::format(" ± {} (95% confidence)", formatNumber(c.fit_slope_ci95, 2))
            : std::string(" (two points: no confidence interval)"));
  }
  return htmlSection(
      "convergence", "Convergence",
      fit + "<div class=\"charts\">\n" + logLogChart(plot) + "\n" + table.html() + "</div>\n");
}

std::string trendsSection(const results::RunResults& results, const results::JobResult& job,
                          const ReportContext& context) {
  std::vector<const results::RunResults*> runs;
  for (const results::RunResults& run : context.history) runs.push_back(&run);
  if (runs.empty() || runs.back()->run.id != results.run.id) runs.push_back(&results);
  if (runs.size() < 2) return {};
  // Every metric value of the job (against its class reference), the primary one first, then the
  // frame time.
  std::vector<std::string> names;
  if (!results.primary_metric.empty() && job.metric(results.primary_metric))
    names.push_back(results.primary_metric);
  for (const auto& [name, value] : job.metrics)
    if (name != results.primary_metric) names.push_back(name);
  std::string charts;
  for (const std::string& name : names) {
    const std::vector<TrendPoint> metric =
        trendOf(runs, job.id, [&](const results::JobResult& j) { return j.metric(name); });
    if (anyFinite(metric))
      charts +=
          trendChart(fmt::format("{} over the last {} runs", name, runs.size()), name, metric);
  }
  const std::vector<TrendPoint> frame =
      trendOf(runs, job.id, [](const results::JobResult& j) { return j.frameMedianMs(); });
  if (anyFinite(frame))
    charts += trendChart(fmt::format("Median frame time over the last {} runs", runs.size()), "ms",
                         frame);
  if (charts.empty()) return {};
  return htmlSection("trends", "Trends",
                     "<p class=\"muted\">Runs of this suite from the history database, oldest "
                     "first; the red point is this run; * marks a build with uncommitted "
                     "changes.</p>\n<div class=\"charts\">\n" +
                         charts + "\n</div>\n");
}

}  // namespace gib::reports
