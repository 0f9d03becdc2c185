#include "reports/paper_table.h"

#include "reports/html_text.h"
#include "reports/number_format.h"
#include "reports/paper_check.h"
#include "reports/report_labels.h"
#include "reports/report_page.h"
#include "reports/run_comparison.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <set>

namespace gib::reports {

namespace {

// Which rows a table shows: one job's (no job column), or those of a set of jobs or of every job
// (a job column linking to the job pages from a page `depth` directories below the run
// directory).
struct PaperRows {
  const std::string* job_id = nullptr;
  const std::set<std::string>* jobs = nullptr;  // null: every job
  int depth = 0;
};

bool shown(const results::PaperValue& paper, const PaperRows& rows) {
  if (rows.job_id) return paper.job == *rows.job_id;
  return !rows.jobs || rows.jobs->contains(paper.job);
}

// The verdict of a value with a tolerance, in the report's verdict colours: reproduced (green),
// not (red), or not judged because the job failed or is absent (grey).
std::string toleranceCell(const PaperCheck& check) {
  const std::string text = paperVerdictText(check);
  if (text.empty()) return {};
  const std::optional<results::Verdict> verdict =
      check.verdict == PaperVerdict::kWithin    ? std::optional(results::Verdict::kImproved)
      : check.verdict == PaperVerdict::kOutside ? std::optional(results::Verdict::kRegressed)
                                                : std::nullopt;
  return fmt::format("<span class=\"{}\">{}</span>", verdictClass(verdict), escapeHtml(text));
}

std::string paperRowsTable(const results::RunResults& results, const PaperRows& rows) {
  const std::string* job_id = rows.job_id;
  // The tolerance column only where a shown value has one: most paper values are times from
  // other hardware, with nothing to judge.
  const bool tolerances =
      std::any_of(results.paper.begin(), results.paper.end(),
                  [&](const results::PaperValue& p) { return shown(p, rows) && p.tolerance; });
  std::vector<TableColumn> columns;
  if (!job_id) columns.push_back({"job"});
  for (TableColumn column : std::vector<TableColumn>{{"quantity"},
                                                     {"paper", true},
                                                     {"ours", true},
                                                     {"ours / paper", true},
                                                     {"tolerance"},
                                                     {"source"},
                                                     {"note"}})
    if (tolerances || column.heading != "tolerance") columns.push_back(std::move(column));
  HtmlTable table(columns);
  for (const results::PaperValue& paper : results.paper) {
    if (!shown(paper, rows)) continue;
    const PaperCheck check = checkPaperValue(results, paper);
    const results::JobResult* job = check.job;
    const std::string unit = paper.unit.empty() ? "" : " " + paper.unit;
    std::string ours_text = "not measured", ratio;
    if (check.ours) {
      ours_text = escapeHtml(formatNumber(*check.ours) + unit);
      if (paper.value != 0) ratio = formatNumber(*check.ours / paper.value, 3);
    }
    std::vector<std::string> row;
    if (!job_id)
      row.push_back(job ? fmt::format("<a href=\"{}\">{}</a>",
                                      escapeHtml(outputHref(jobPageFile(*job), rows.depth)),
                                      escapeHtml(paper.job))
                        : escapeHtml(paper.job));
    for (std::string cell : {escapeHtml(paper.quantity),
                             escapeHtml(formatNumber(paper.value) + unit), ours_text, ratio})
      row.push_back(std::move(cell));
    if (tolerances) row.push_back(toleranceCell(check));
    row.push_back(escapeHtml(paper.source));
    row.push_back(escapeHtml(paper.note));
    table.addRow(row);
  }
  if (table.empty()) return {};
  return std::string(
             "<p class=\"muted\">Timings come from different hardware: compare ratios "
             "between jobs rather than absolute times.") +
         (tolerances ? " A tolerance marks a value we should reproduce: ours is within it when "
                       "|ours − paper| ≤ tolerance·|paper|."
                     : "") +
         "</p>\n" + table.html();
}

}  // namespace

std::string paperTable(const results::RunResults& results, const std::string* job_id) {
  return paperRowsTable(results, {job_id, nullptr, 0});
}

std::string paperTable(const results::RunResults& results, const std::set<std::string>& jobs,
                       int depth) {
  return paperRowsTable(results, {nullptr, &jobs, depth});
}

}  // namespace gib::reports
