#include "reports/figure_page.h"

#include "reports/figure_charts.h"
#include "reports/figure_panels.h"
#include "reports/html_text.h"
#include "reports/number_format.h"
#include "reports/paper_table.h"
#include "reports/report_labels.h"
#include "reports/report_page.h"
#include "reports/svg_charts.h"
#include "results/quantity.h"

#include <fmt/format.h>
#include <fnmatch.h>

#include <algorithm>
#include <optional>
#include <set>

namespace gib::reports {

namespace {

namespace fs = std::filesystem;

// The page is report/figure-<name>.html: one directory below the run directory.
constexpr int kDepth = 1;

bool present(const fs::path& run_dir, const std::string& file) {
  std::error_code ec;
  return fs::is_regular_file(run_dir / file, ec);
}

std::string jobLink(const results::JobResult* job, const std::string& id) {
  if (!job) return escapeHtml(id);
  return fmt::format("<a href=\"{}\">{}</a>", escapeHtml(outputHref(jobPageFile(*job), kDepth)),
                     escapeHtml(id));
}

std::string panelHtml(const fs::path& run_dir, const results::RunResults& results,
                      const results::FigureSpec::Panel& panel) {
  const PanelPicture picture = panelPicture(run_dir, results, panel);
  std::string html = fmt::format(
      "<div class=\"figure-panel\" data-row=\"{0}\" data-column=\"{1}\" style=\"grid-row: {0}; "
      "grid-column: {1}\">\n",
      panel.row, panel.column);
  if (picture.path.empty()) {
    html += fmt::format("<div class=\"figure-absent\">No picture: {}.</div>\n",
                        escapeHtml(picture.absent));
  } else {
    const std::string alt =
        panel.caption.empty() ? fmt::format("{} of {}", panel.image, panel.job) : panel.caption;
    const std::string image =
        fmt::format("<img src=\"{}\" alt=\"{}\">", escapeHtml(outputHref(picture.path, kDepth)),
                    escapeHtml(alt));
    html += picture.job
                ? fmt::format("<a href=\"{}\">{}</a>\n",
                              escapeHtml(outputHref(jobPageFile(*picture.job), kDepth)), image)
                : image + "\n";
  }
  if (!panel.caption.empty())
    html += fmt::format("<p class=\"figure-panel-caption\">{}</p>\n", escapeHtml(panel.caption));
  if (const std::string value = panelValueText(results, picture.job, panel.metric); !value.empty())
    html += fmt::format("<p class=\"figure-panel-value\">{}</p>\n", escapeHtml(value));
  html += fmt::format("<p class=\"figure-panel-job muted\">{} · {}</p>\n</div>\n",
                      jobLink(picture.job, panel.job), escapeHtml(panel.image));
  return html;
}

std::string grid(const fs::path& run_dir, const results::RunResults& results,
                 const results::FigureSpec& figure) {
  std::string panels;
  for (const results::FigureSpec::Panel& panel : figure.panels)
    panels += panelHtml(run_dir, results, panel);
  std::string html = fmt::format(
      "<figure class=\"figure\">\n<div class=\"figure-grid\" style=\"grid-template-columns: "
      "repeat({0}, auto); --figure-columns: {0}\">\n{1}</div>\n",
      figure.columns, panels);
  if (!figure.caption.empty())
    html += fmt::format("<figcaption>{}</figcaption>\n", escapeHtml(figure.caption));
  return html + "</figure>\n";
}

// The suite's charts over any of the figure's jobs, each with its standalone SVG.
std::string chartsSection(const fs::path& run_dir, const results::RunResults& results,
                          const std::vector<std::string>& jobs) {
  std::string charts;
  for (std::size_t i = 0; i < results.charts.size(); ++i) {
    const results::ChartSpec& chart = results.charts[i];
    if (std::none_of(jobs.begin(), jobs.end(), [&](const std::string& id) {
          return fnmatch(chart.jobs.c_str(), id.c_str(), 0) == 0;
        }))
      continue;
    const std::string file = chartSvgFile(results, i);
    const std::string download =
        present(run_dir, file)
            ? fmt::format("<p class=\"figure-download\">Download: <a href=\"{}\">SVG</a></p>\n",
                          escapeHtml(outputHref(file, kDepth)))
            : std::string();
    charts += "<div class=\"figure-chart\">\n" + seriesChart(chartPlot(results, chart)) + "\n" +
              download + "</div>\n";
  }
  if (charts.empty()) return {};
  return htmlSection("charts", "Charts of these jobs",
                     "<div class=\"charts\">\n" + charts + "</div>\n");
}

}  // namespace

std::string panelValueText(const results::RunResults& results, const results::JobResult* job,
                           const std::string& metric) {
  const std::string quantity = metric.empty() ? results.primary_metric : metric;
  if (quantity.empty() || quantity == "none") return {};
  const bool timing = !results::quantityPasses(quantity).empty();
  const std::string label = timing ? quantity : results::quantityLabel(quantity);
  const std::optional<double> value =
      job ? results::quantityValue(*job, quantity) : std::optional<double>();
  if (!value) return label + ": not measured";
  return fmt::format("{}: {}{}", label, formatNumber(*value), timing ? " ms" : "");
}

std::string figurePage(const fs::path& run_dir, const results::RunResults& results,
                       const results::FigureSpec& figure) {
  std::string body = fmt::format(
      "<p><a href=\"../index.html\">← {} report</a></p>\n<h1>{}</h1>\n<p class=\"muted\">Figure "
      "{} of suite {} · run {}</p>\n",
      escapeHtml(results.run.suite), escapeHtml(figure.title), escapeHtml(figure.name),
      escapeHtml(results.run.suite), escapeHtml(results.run.id));
  body += rendererNote(results.run.gl_renderer, "the run's technique jobs");
  const std::vector<std::string> jobs = figureJobs(figure);
  const std::string paper =
      paperTable(results, std::set<std::string>(jobs.begin(), jobs.end()), kDepth);
  const std::string charts = chartsSection(run_dir, results, jobs);
  const std::string png = figurePngFile(figure);
  body += present(run_dir, png)
              ? fmt::format(
                    "<p class=\"figure-download\">Download: <a href=\"{}\">PNG</a> (the "
                    "panels in one picture){}</p>\n",
                    escapeHtml(outputHref(png, kDepth)),
                    charts.empty() ? "" : "; each chart as SVG under it")
              : std::string(
                    "<p class=\"note\">No picture of the whole figure: none of its "
                    "panels has a picture.</p>\n");
  std::string aside;
  if (!paper.empty()) aside += htmlSection("paper", "The paper's numbers beside ours", paper);
  aside += charts;
  body += "<div class=\"figure-page\">\n" + grid(run_dir, results, figure);
  if (!aside.empty()) body += "<div class=\"figure-aside\">\n" + aside + "</div>\n";
  body += "</div>\n";
  return htmlPage(fmt::format("{}: {}", figure.title, results.run.suite), body);
}

}  // namespace gib::reports
