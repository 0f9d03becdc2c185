#include "reports/solid_angle_bench_page.h"

#include "reports/html_text.h"
#include "reports/report_page.h"
#include "reports/svg_charts.h"

#include <fmt/format.h>

namespace gib::reports {

namespace {

std::string errorTable(const std::vector<SolidAngleBenchRow>& rows) {
  HtmlTable table({{"scheme"},
                   {"image", true},
                   {"mean |error| (sr)", true},
                   {"relative", true},
                   {"SD of error (sr)", true},
                   {"max |error| (sr)", true},
                   {"mean error (bias, sr)", true}});
  for (const SolidAngleBenchRow& r : rows)
    table.addRow({escapeHtml(r.scheme), fmt::format("{0}×{0}", r.size),
                  fmt::format("{:.3e}", r.mean_abs_error),
                  fmt::format("{:.2e}", r.mean_exact > 0 ? r.mean_abs_error / r.mean_exact : 0),
                  fmt::format("{:.3e}", r.sd_error), fmt::format("{:.3e}", r.max_abs_error),
                  fmt::format("{:+.2e}", r.mean_error)});
  return table.html();
}

std::vector<PassBar> phaseBars(const std::vector<SolidAngleBenchRow>& rows) {
  std::vector<PassBar> bars;
  for (const SolidAngleBenchRow& r : rows) {
    const double total = r.render_ms.median + r.read_back_ms.median + r.weight_ms.median;
    bars.push_back({fmt::format("{} {}²", r.scheme, r.size), 0, total, total, total});
    for (const auto& [name, phase] :
         {std::pair{"render", &r.render_ms}, std::pair{"read back", &r.read_back_ms},
          std::pair{"weight", &r.weight_ms}})
      bars.push_back({name, 1, phase->median, phase->first_quartile, phase->third_quartile});
  }
  return bars;
}

std::string figureGrid(const std::vector<SolidAngleBenchFigure>& figures) {
  // Side by side, as the paper's Fig. 8 sets its three panels.
  std::string html = fmt::format(
      "<div class=\"figure-grid\" style=\"grid-template-columns: repeat({}, minmax(0, 1fr))\">",
      figures.size());
  for (const SolidAngleBenchFigure& f : figures)
    html += fmt::format(
        "<figure><img src=\"{}\" alt=\"{}\" style=\"max-width: 100%\"><figcaption>{}</figcaption>"
        "</figure>",
        escapeHtml(urlPath(f.png)), escapeHtml(f.label), escapeHtml(f.label));
  html += "</div>";
  html +=
      "<p>|estimate − exact| over the receiving plane, seen from above (x to the right, z "
      "downwards), magma from 0 to each panel's largest error (its colour bar, in sr).</p>";
  return html;
}

}  // namespace

std::string solidAngleBenchPage(const std::vector<std::pair<std::string, std::string>>& facts,
                                const std::vector<SolidAngleBenchRow>& rows,
                                const std::vector<SolidAngleBenchFigure>& figures) {
  std::string body = "<h1>Hardware sampling of an area light: the bench test</h1>";
  body +=
      "<p>Fournier &amp; Péroche §6.1: a square light partly hidden by a square occluder whose "
      "edges are aligned with the sampling grid; each scheme estimates the visible solid angle at "
      "every point of a grid on the receiving plane, against the exact value.</p>";
  body += factsTable(facts);
  body += htmlSection("errors", "Error of the visible solid angle (Fig. 7)", errorTable(rows));
  if (!figures.empty())
    body += htmlSection("distribution", "The error over the plane (Fig. 8)", figureGrid(figures));
  const std::size_t samples = rows.empty() ? 0 : rows.front().render_ms.count;
  const std::string phases =
      samples == 0 ? std::string("<p>Not timed (<code>--timing-samples 0</code>).</p>")
                   : fmt::format(
                         "<p>Median and quartiles of {} points per scheme and size, wall clock of "
                         "the calling thread: drawing finished with glFinish, the read-back, the "
                         "CPU weighting.</p>",
                         samples) +
                         passTimingChart(phaseBars(rows), "point");
  body += htmlSection("phases", "Time of each phase per point (Fig. 9)", phases);
  return htmlPage("Hardware sampling of an area light", body);
}

}  // namespace gib::reports
