#include "reports/figure_charts.h"

#include "reports/figure_panels.h"
#include "reports/html_text.h"
#include "reports/number_format.h"
#include "reports/paper_table.h"
#include "reports/report_labels.h"
#include "reports/report_page.h"
#include "results/quantity.h"

#include <fmt/format.h>
#include <fnmatch.h>

#include <algorithm>
#include <cctype>
#include <set>

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

constexpr std::size_t kMaxSlugLength = 80;

std::string titleSlug(const std::string& title) {
  std::string slug;
  for (char c : title) {
    if (std::isalnum(static_cast<unsigned char>(c)))
      slug += char(std::tolower(static_cast<unsigned char>(c)));
    else if (!slug.empty() && slug.back() != '-')
      slug += '-';
  }
  if (slug.size() > kMaxSlugLength) slug.resize(kMaxSlugLength);
  while (!slug.empty() && slug.back() == '-') slug.pop_back();
  return slug;
}

// Links to the figure pages, each with the first panel's picture that the run has.
std::string figureLinks(const std::filesystem::path& run_dir, const results::RunResults& results) {
  std::string links;
  for (const results::FigureSpec& figure : results.figures) {
    std::string preview;
    for (const results::FigureSpec::Panel& panel : figure.panels) {
      const PanelPicture picture = panelPicture(run_dir, results, panel);
      if (picture.path.empty()) continue;
      preview = fmt::format("<img src=\"{}\" alt=\"\">", escapeHtml(outputHref(picture.path, 0)));
      break;
    }
    links +=
        fmt::format("<a class=\"figure-link\" href=\"{}\">{}<span>{}</span></a>\n",
                    escapeHtml(urlPath(figurePageFile(figure))), preview, escapeHtml(figure.title));
  }
  if (links.empty()) return {};
  return "<p class=\"muted\">The document's figures rebuilt from this run's pictures, each on a "
         "page of its own with its numbers.</p>\n<div class=\"figure-links\">\n" +
         links + "</div>\n";
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

std::string standaloneChartSvg(const results::RunResults& results,
                               const results::ChartSpec& chart) {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + seriesChart(chartPlot(results, chart)) +
         "\n";
}

std::vector<std::string> chartSlugs(const std::vector<results::ChartSpec>& charts) {
  std::vector<std::string> slugs;
  std::set<std::string> given;
  for (std::size_t i = 0; i < charts.size(); ++i) {
    std::string base = titleSlug(charts[i].title);
    if (base.empty()) base = fmt::format("chart-{}", i + 1);
    std::string slug = base;
    for (int n = 2; given.contains(slug); ++n) slug = fmt::format("{}-{}", base, n);
    given.insert(slug);
    slugs.push_back(slug);
  }
  return slugs;
}

std::string chartSvgFile(const results::RunResults& results, std::size_t index) {
  return "figures/" + chartSlugs(results.charts).at(index) + ".svg";
}

std::string figuresSection(const std::filesystem::path& run_dir,
                           const results::RunResults& results) {
  std::string charts;
  for (const results::ChartSpec& chart : results.charts)
    charts += seriesChart(chartPlot(results, chart)) + "\n";
  const std::string paper = paperTable(results, nullptr);
  const std::string figures = figureLinks(run_dir, results);
  if (charts.empty() && paper.empty() && figures.empty()) return {};
  std::string body = figures;
  if (!charts.empty())
    body +=
        "<p class=\"muted\">Hover over a point for its job. Jobs lacking either quantity "
        "are left out.</p>\n<div class=\"charts\">\n" +
        charts + "</div>\n";
  if (!paper.empty()) body += "<h3>The paper's numbers beside ours</h3>\n" + paper;
  return htmlSection("figures", "Figures", body);
}

}  // namespace gib::reports
