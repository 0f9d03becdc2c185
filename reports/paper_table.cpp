#include "reports/paper_table.h"

#include "reports/html_text.h"
#include "reports/number_format.h"
#include "reports/report_labels.h"
#include "reports/report_page.h"
#include "results/quantity.h"

#include <fmt/format.h>

#include <optional>

namespace gib::reports {

std::string paperTable(const results::RunResults& results, const std::string* job_id) {
  std::vector<TableColumn> columns;
  if (!job_id) columns.push_back({"job"});
  for (TableColumn column : std::vector<TableColumn>{{"quantity"},
                                                     {"paper", true},
                                                     {"ours", true},
                                                     {"ours / paper", true},
                                                     {"source"},
                                                     {"note"}})
    columns.push_back(std::move(column));
  HtmlTable table(columns);
  for (const results::PaperValue& paper : results.paper) {
    if (job_id && paper.job != *job_id) continue;
    const results::JobResult* job = results.findJob(paper.job);
    const std::string unit = paper.unit.empty() ? "" : " " + paper.unit;
    std::string ours_text = "not measured", ratio;
    if (job)
      if (const std::optional<double> ours = results::quantityValue(*job, paper.quantity)) {
        ours_text = escapeHtml(formatNumber(*ours) + unit);
        if (paper.value != 0) ratio = formatNumber(*ours / paper.value, 3);
      }
    std::vector<std::string> row;
    if (!job_id)
      row.push_back(job ? fmt::format("<a href=\"{}\">{}</a>",
                                      escapeHtml(urlPath(jobPageFile(*job))), escapeHtml(paper.job))
                        : escapeHtml(paper.job));
    for (std::string cell :
         {escapeHtml(paper.quantity), escapeHtml(formatNumber(paper.value) + unit), ours_text,
          ratio, escapeHtml(paper.source), escapeHtml(paper.note)})
      row.push_back(std::move(cell));
    table.addRow(row);
  }
  if (table.empty()) return {};
  return "<p class=\"muted\">Timings come from different hardware: compare ratios between jobs "
         "rather than absolute times.</p>\n" +
         table.html();
}

}  // namespace gib::reports
