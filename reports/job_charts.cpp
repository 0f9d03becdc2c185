#include "reports/job_charts.h"

#include "reports/html_text.h"
#include "reports/number_format.h"
#include "reports/pass_timings_view.h"
#include "reports/report_labels.h"
#include "reports/report_page.h"
#include "reports/svg_charts.h"

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <limits>

namespace gib::reports {

namespace {

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

std::string timingsIntro(const TimingsView& view, const std::optional<JobComparison>& compared) {
  std::string intro =
      fmt::format("<p>{}; {} warm-up and {} measured frames.",
                  escapeHtml(view.clock_description.empty() ? view.clock : view.clock_description),
                  view.warmup_frames, view.measured_frames);
  const double frame = view.passes.front().median_ms;
  if (std::isfinite(frame))
    intro += fmt::format(" Median frame {} ms", escapeHtml(formatNumber(frame)));
  if (view.frame_rate_fps) intro += fmt::format(" ({} fps)", formatNumber(*view.frame_rate_fps, 3));
  if (compared && compared->timing) {
    const TimingChange& t = *compared->timing;
    intro += fmt::format("; previous run {} ms, now {} (Mann–Whitney p = {})",
                         formatNumber(t.base_median_ms),
                         verdictSpan(formatNumber(t.next_median_ms) + " ms", compared->timing),
                         formatNumber(t.p_value, 2));
  }
  return intro + ".</p>\n";
}

// `unit`: what one sample times, "frame" or "iteration".
std::string passTable(const TimingsView& view, std::string_view unit) {
  HtmlTable table({{"pass"},
                   {"median ms", true},
                   {"first quartile", true},
                   {"third quartile", true},
                   {fmt::format("share of {}", unit), true},
                   {fmt::format("calls per {}", unit), true}});
  for (const PassTimes& pass : view.passes)
    table.addRow({fmt::format("<span style=\"padding-left:{}em\">{}</span>",
                              1.2 * std::max(0, pass.depth), escapeHtml(pass.name)),
                  formatNumber(pass.median_ms), formatNumber(pass.first_quartile_ms),
                  formatNumber(pass.third_quartile_ms), formatShare(pass.share),
                  formatNumber(pass.calls_per_frame, 3)});
  return table.html();
}

std::string phasesTable(const JobResult& job) {
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
std::string convergenceMetric(const Convergence& convergence, const std::string& primary) {
  if (!convergence.fit_metric.empty()) return convergence.fit_metric;
  const NamedValues& first = convergence.points.front().metrics;
  for (const auto& [name, value] : first)
    if (name == primary) return primary;
  return first.empty() ? primary : first.front().first;
}

double valueOf(const NamedValues& values, const std::string& name) {
  for (const auto& [key, value] : values)
    if (key == name) return value;
  return kNoValue;
}

// One run's value of a job, for a trend; NaN when the run lacks the job or the value.
using JobValue = std::function<std::optional<double>(const JobResult&)>;

std::vector<TrendPoint> trendOf(const std::vector<const RunResults*>& runs, const std::string& id,
                                const JobValue& value) {
  std::vector<TrendPoint> points;
  for (const RunResults* run : runs) {
    const JobResult* job = run->findJob(id);
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

std::string timingsSection(const JobResult& job, const std::optional<JobComparison>& compared) {
  const std::optional<TimingsView> view = readTimings(job.timings);
  const std::string phases = phasesTable(job);
  if (!view) return phases.empty() ? std::string() : htmlSection("timings", "Timings", phases);
  return htmlSection("timings", "Timings",
                     timingsIntro(*view, compared) + "<div class=\"charts\">\n" +
                         passTable(*view, "frame") + passTimingChart(passBars(*view)) +
                         "\n</div>\n" + phases);
}

std::string iterationTimingsSection(const JobResult& job) {
  const std::optional<TimingsView> view = readTimings(job.iteration_timings);
  if (!view) return {};
  const std::string intro = fmt::format(
      "<p>{}; {} iterations, each timed as one unit. Median iteration {} ms.</p>\n",
      escapeHtml(view->clock_description.empty() ? view->clock : view->clock_description),
      view->measured_frames, escapeHtml(formatNumber(view->passes.front().median_ms)));
  return htmlSection("iteration-timings", "Time per iteration",
                     intro + "<div class=\"charts\">\n" + passTable(*view, "iteration") +
                         passTimingChart(passBars(*view), "iteration") + "\n</div>\n");
}

std::string convergenceSection(const JobResult& job, const std::string& primary_metric) {
  if (!job.convergence || job.convergence->points.empty()) return {};
  const Convergence& c = *job.convergence;
  const std::string metric = convergenceMetric(c, primary_metric);
  LogLogPlot plot{fmt::format("Convergence of {}", metric), c.x_label, metric, {}, std::nullopt};
  HtmlTable table({{c.x_label}, {metric, true}, {"seconds", true}});
  for (const Convergence::Point& point : c.points) {
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

std::string trendsSection(const RunResults& results, const JobResult& job,
                          const ReportContext& context) {
  std::vector<const RunResults*> runs;
  for (const RunResults& run : context.history) runs.push_back(&run);
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
        trendOf(runs, job.id, [&](const JobResult& j) { return j.metric(name); });
    if (anyFinite(metric))
      charts +=
          trendChart(fmt::format("{} over the last {} runs", name, runs.size()), name, metric);
  }
  const std::vector<TrendPoint> frame =
      trendOf(runs, job.id, [](const JobResult& j) { return j.frameMedianMs(); });
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
