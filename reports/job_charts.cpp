#include "reports/job_charts.h"

#include "reports/html_text.h"
#include "reports/metric_labels.h"
#include "reports/number_format.h"
#include "reports/report_labels.h"
#include "reports/report_page.h"
#include "reports/svg_charts.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace gib::reports {

namespace {

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

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
  return results::findValue(values, name).value_or(kNoValue);
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

std::string convergenceSection(const results::JobResult& job, const std::string& primary_metric) {
  if (!job.convergence || job.convergence->points.empty()) return {};
  const results::Convergence& c = *job.convergence;
  const std::string metric = convergenceMetric(c, primary_metric);
  const std::string label = metricLabel(metric);
  LogLogPlot plot{
      fmt::format("Convergence of {}{}", label, c.fit_metric.empty() ? "" : " (fitted)"),
      c.x_label,
      label,
      {},
      std::nullopt};
  HtmlTable table({{c.x_label}, {label, true}, {"seconds", true}});
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
        "<p>The fit follows {}: least-squares slope of its log against log {}: "
        "<strong>{}</strong>{} (Monte Carlo noise alone falls with slope −0.5 for RMSE, −1 for MSE "
        "and relMSE).</p>\n",
        metricLabelHtml(metric), escapeHtml(c.x_label),
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
