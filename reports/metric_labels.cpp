#include "reports/metric_labels.h"

#include "common/join.h"
#include "metrics/metric_registry.h"
#include "reports/html_text.h"
#include "reports/number_format.h"
#include "reports/report_page.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

namespace gib::reports {

namespace {

// The metric that declares `value`; nullptr for a value no metric declares (one since removed).
const metrics::MetricInfo* declaringMetric(std::string_view value) {
  for (const metrics::MetricInfo& metric : metrics::metricCatalogue())
    for (const metrics::MetricValueInfo& declared : metric.values)
      if (declared.name == value) return &metric;
  return nullptr;
}

bool isFlip(const metrics::MetricInfo& metric) {
  return metric.name == "flip" || metric.name == "hdrflip";
}

std::string directionText(std::string_view value) {
  const metrics::MetricValueInfo* info = metrics::findMetricValue(value);
  if (!info) return "not declared by the metric registry";
  switch (info->direction) {
    case metrics::MetricDirection::kLowerIsBetter:
      return "lower is better";
    case metrics::MetricDirection::kHigherIsBetter:
      return "higher is better";
    case metrics::MetricDirection::kTowardOne:
      return "closer to 1 is better";
    case metrics::MetricDirection::kDescriptive:
      return "describes the error: neither way is better";
  }
  return {};
}

// The parameters the harness computes the metric with: MetricOptions' defaults, which it never
// changes. The relative metrics name their ε ("eps") in the registry's description.
std::string parametersText(const metrics::MetricInfo& metric) {
  const metrics::MetricOptions defaults;
  if (metric.description.find("eps") != std::string::npos)
    return fmt::format("\u03b5 = {}", formatNumber(defaults.relative_epsilon));
  if (isFlip(metric))
    return fmt::format("{} pixels per degree", formatNumber(defaults.flip.pixels_per_degree));
  return {};
}

// "lower is better" when the values agree; else each direction with its values:
// "lower is better: relmse, relmse_trim1pct; describes the error…: relmse_top1pct_share".
std::string directionsText(const std::vector<std::string>& values) {
  std::vector<std::pair<std::string, std::vector<std::string>>> groups;
  for (const std::string& value : values) {
    const std::string direction = directionText(value);
    auto group = std::find_if(groups.begin(), groups.end(),
                              [&](const auto& g) { return g.first == direction; });
    if (group == groups.end()) group = groups.insert(groups.end(), {direction, {}});
    group->second.push_back(metricLabel(value));
  }
  if (groups.size() == 1) return groups.front().first;
  return joinNames(groups, "; ",
                   [](const auto& g) { return g.first + ": " + joinNames(g.second, ", "); });
}

}  // namespace

std::string metricLabel(std::string_view value) {
  const metrics::MetricValueInfo* info = metrics::findMetricValue(value);
  return info && !info->label.empty() ? info->label : std::string(value);
}

std::string metricDescription(std::string_view value) {
  const metrics::MetricInfo* metric = declaringMetric(value);
  if (!metric) return fmt::format("{}: {}", value, directionText(value));
  std::string text = metric->description;
  if (const metrics::MetricValueInfo* info = metrics::findMetricValue(value);
      !info->description.empty())
    text += ": " + info->description;
  text += "; " + directionText(value);
  if (const std::string parameters = parametersText(*metric); !parameters.empty())
    text += "; " + parameters;
  return text + fmt::format("; results.json: {}", value);
}

std::string metricLabelHtml(std::string_view value) {
  return fmt::format("<span class=\"metric-name\" title=\"{}\">{}</span>",
                     escapeHtml(metricDescription(value)), escapeHtml(metricLabel(value)));
}

std::string metricLegend(const std::vector<std::string>& values) {
  // A row per metric (relMSE's several values share its definition), in first-seen order; a
  // value no metric declares has a row of its own.
  std::vector<std::pair<const metrics::MetricInfo*, std::vector<std::string>>> rows;
  for (const std::string& value : values) {
    const metrics::MetricInfo* metric = declaringMetric(value);
    auto row = std::find_if(rows.begin(), rows.end(),
                            [&](const auto& r) { return metric && r.first == metric; });
    if (row == rows.end()) row = rows.insert(rows.end(), {metric, {}});
    if (std::find(row->second.begin(), row->second.end(), value) == row->second.end())
      row->second.push_back(value);
  }
  HtmlTable table({{"metric"}, {"definition"}, {"better"}, {"parameters"}}, "metric-legend");
  for (const auto& [metric, shown] : rows)
    table.addRow({joinNames(shown, ", ", metricLabelHtml),
                  escapeHtml(metric ? metric->description : std::string("(not in the registry)")),
                  escapeHtml(directionsText(shown)),
                  escapeHtml(metric ? parametersText(*metric) : std::string())});
  return table.empty() ? std::string() : table.html();
}

}  // namespace gib::reports
