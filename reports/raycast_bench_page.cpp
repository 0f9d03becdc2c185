#include "reports/raycast_bench_page.h"

#include "reports/html_text.h"
#include "reports/report_page.h"
#include "reports/svg_charts.h"

#include <fmt/format.h>

#include <map>

namespace gib::reports {

namespace {

std::string bytesText(const std::optional<std::size_t>& bytes) {
  if (!bytes) return "—";
  return fmt::format("{:.2f} MiB", double(*bytes) / (1024.0 * 1024.0));
}

std::string caseTable(const RaycastCase& c) {
  HtmlTable table({{"structure"},
                   {"mismatches", true},
                   {"ties", true},
                   {"max |Δt|", true},
                   {"max barycentric error", true},
                   {"M rays/s", true},
                   {"cast (ms, median)", true},
                   {"build (ms)", true},
                   {"memory", true},
                   {"pairs kept by cones", true}});
  for (const RaycastStructureRow& r : c.structures) {
    if (!r.skipped.empty()) {
      table.addRow({escapeHtml(r.name), "skipped: " + escapeHtml(r.skipped), "", "", "", "", "", "",
                    "", ""});
      continue;
    }
    const bool reference = r.name == "embree";
    table.addRow(
        {escapeHtml(r.name), reference ? "(reference)" : std::to_string(r.mismatches),
         reference ? "" : std::to_string(r.ties),
         reference ? "" : fmt::format("{:.2e}", r.max_abs_dt),
         reference ? "" : fmt::format("{:.2e}", r.max_barycentric_error),
         fmt::format("{:.3g}", r.mrays_per_second), fmt::format("{:.3g}", r.cast_ms.median),
         fmt::format("{:.3g}", r.build_ms), bytesText(r.bytes),
         r.kept_pair_fraction ? fmt::format("{:.1f} %", 100.0 * *r.kept_pair_fraction) : ""});
  }
  return fmt::format(
             "<p>{} rays ({} hit something in Embree) against {} triangles; tie distance δ = "
             "{:.3g} scene units.</p>",
             c.ray_count, c.reference_hits, c.triangles, c.tie_distance) +
         table.html();
}

// Per kind of rays, M rays/s against triangle count, one series per structure.
std::string rateCharts(const std::vector<RaycastCase>& cases) {
  std::map<std::string, std::map<std::string, std::vector<ChartPoint>>> by_kind;
  for (const RaycastCase& c : cases)
    for (const RaycastStructureRow& r : c.structures)
      if (r.skipped.empty() && r.mrays_per_second > 0)
        by_kind[c.rays][r.name].push_back({double(c.triangles), r.mrays_per_second, c.scene});
  std::string html;
  for (const auto& [kind, structures] : by_kind) {
    SeriesPlot plot;
    plot.title = fmt::format("{} rays: M rays/s against triangles", kind);
    plot.x_label = "triangles";
    plot.y_label = "M rays/s";
    plot.log_x = plot.log_y = true;
    for (const auto& [name, points] : structures) plot.series.push_back({name, points});
    html += seriesChart(plot);
  }
  return html;
}

}  // namespace

std::string raycastBenchPage(const std::vector<std::pair<std::string, std::string>>& facts,
                             const std::vector<RaycastCase>& cases) {
  std::string body = "<h1>Ray casting on the GPU against Embree</h1>";
  body +=
      "<p>Book Ch. 5: the same rays cast by Embree on every CPU core and by each GPU structure "
      "(the §5.1 triangle test alone, the ray engine of §5.2 and its cones of §5.3, the loose "
      "kd-tree of §5.5, and a BVH of today's kind). A mismatch is a ray whose GPU hit differs "
      "from Embree's beyond the tie rule (realtime/ray_casting/README.md): a different triangle "
      "farther than δ along the ray, or a hit against a miss away from the triangle's edges. The "
      "book reports 10–20 M rays/s on 10 000–100 000 triangles, depending on coherence.</p>";
  body += factsTable(facts);
  std::string tables;
  for (const RaycastCase& c : cases)
    tables +=
        fmt::format("<h3>{}, {} rays</h3>", escapeHtml(c.scene), escapeHtml(c.rays)) + caseTable(c);
  body += htmlSection("table", "Hits and speed per structure", tables);
  body += htmlSection("rates", "Rays per second against triangle count", rateCharts(cases));
  return htmlPage("Ray casting on the GPU against Embree", body);
}

}  // namespace gib::reports
