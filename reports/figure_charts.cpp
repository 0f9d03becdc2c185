#include "reports/figure_charts.h"

#include "reports/html_text.h"
#include "reports/number_format.h"
#include "reports/paper_table.h"
#include "reports/report_page.h"
#include "results/quantity.h"

#include <fmt/format.h>
#include <fnmatch.h>

#include <algorithm>

namespace gib::reports {

namespace {

// The value a chart's series groups points by: a parameter's canonical value ("hemicube"), the
// scene, else the number as the report prints it; nullopt when the job lacks it.
std::optional<std::string> seriesValue(const results::JobResult& job, const std::string& quantity) {
  if (quantity == "scene") return job.scene;
  if (quantity.starts_with(results::kParameterPrefix))
    return results::parameterText(job, quantity.substr(results::kParameterPrefix.size()));
  const std::optional<double> value = results::quantityValue(job, quantity);
  return value ? std::optional<std::string>(formatNumber(*value)) : std::nullopt;
}

}  // namespace

SeriesPlot chartPlot(const results::RunResults& results, const results::ChartSpec& chart) {
  SeriesPlot plot;
  plot.title = chart.title;
  plot.x_label = results::quantityLabel(chart.x);
  plot.y_label = results::quantityLabel(chart.y);
  plot.log_x = chart.log_x;
  plot.log_y = chart.log_y;
  plot.front = chart.front;
  for (const results::JobResult& job : results.jobs) {
    if (fnmatch(chart.jobs.c_str(), job.id.c_str(), 0) != 0) continue;
    const std::optional<double> x = results::quantityValue(job, chart.x);
    const std::optional<double> y = results::quantityValue(job, chart.y);
    if (!x || !y) continue;
    std::string name;
    if (!chart.series.empty())
      name = fmt::format("{} = {}", results::quantityLabel(chart.series),
                         seriesValue(job, chart.series).value_or("(none)"));
    auto series = std::find_if(plot.series.begin(), plot.series.end(),
                               [&](const ChartSeries& s) { return s.name == name; });
    if (series == plot.series.end()) series = plot.series.insert(plot.series.end(), {name, {}});
    series->points.push_back({*x, *y, job.id});
  }
  return plot;
}

std::string figuresSection(const results::RunResults& results) {
  std::string charts;
  for (const results::ChartSpec& chart : results.charts)
    charts += seriesChart(chartPlot(results, chart)) + "\n";
  const std::string paper = paperTable(results, nullptr);
  if (charts.empty() && paper.empty()) return {};
  std::string body;
  if (!charts.empty())
    body +=
        "<p class=\"muted\">Hover over a point for its job. Jobs lacking either quantity "
        "are left out.</p>\n<div class=\"charts\">\n" +
        charts + "</div>\n";
  if (!paper.empty()) body += "<h3>The paper's numbers beside ours</h3>\n" + paper;
  return htmlSection("figures", "Figures", body);
}

}  // namespace gib::reports
