#include "reports/job_page.h"

#include "common/join.h"

#include "reports/html_text.h"
#include "reports/image_viewer.h"
#include "reports/job_charts.h"
#include "reports/number_format.h"
#include "reports/paper_table.h"
#include "reports/report_labels.h"
#include "reports/report_page.h"

#include <fmt/format.h>

#include <cmath>

#include <algorithm>

namespace gib::reports {

namespace {

std::string referenceText(const results::ReferenceUse& use) {
  return fmt::format("{}: {} spp, seed {}, {}; {}", use.key, use.spp, use.seed, use.path_class,
                     use.store_hit ? "from the store"
                                   : fmt::format("rendered by this run in {} s",
                                                 formatNumber(use.render_seconds, 3)));
}

// Statistics are mostly counts: whole numbers in full (16000, not 1.6e+04).
std::string formatCount(double value) {
  if (std::isfinite(value) && std::floor(value) == value && std::abs(value) < 1e15)
    return fmt::format("{:.0f}", value);
  return formatNumber(value);
}

std::string jobFacts(const results::JobResult& job) {
  return factsTable({
      {"case", job.case_name},
      {"scene", job.scene_hash.empty()
                    ? job.scene
                    : fmt::format("{} (hash {})", job.scene, job.scene_hash.substr(0, 12))},
      {"scene parameters", formatAssignments(job.scene_parameters)},
      {"technique", job.technique},
      {"parameters", formatAssignments(job.parameters)},
      {"image", job.width > 0 ? fmt::format("{} × {} pixels", job.width, job.height) : ""},
      {"path class", job.path_class},
      {"statistics",
       joinNames(job.statistics, ", ",
                 [](const auto& s) { return s.first + " " + formatCount(s.second); })},
      {"reference", referenceText(job.reference)},
      {"full reference", job.full_reference ? referenceText(*job.full_reference) : ""},
      {"job time", fmt::format("{} s", formatNumber(job.seconds, 3))},
      {"host", job.execution.host},
      {"Slurm task", job.execution.scheduler_job},
      {"queue wait", job.execution.queue_seconds >= 0
                         ? fmt::format("{} s", formatNumber(job.execution.queue_seconds, 3))
                         : ""},
      {"GL renderer", job.execution.gl_renderer},
  });
}

// Why a job has no result, and its log when the scheduler kept one.
std::string failureSection(const results::JobResult& job) {
  if (!job.failed()) return {};
  std::string html = fmt::format("<p class=\"failure\">{}</p>\n", escapeHtml(job.failure));
  if (!job.outputs.log.empty())
    html += fmt::format("<p>Log: <a href=\"../{}\">{}</a></p>\n",
                        escapeHtml(urlPath(job.outputs.log)), escapeHtml(job.outputs.log));
  return htmlSection("failure", "The job failed", html);
}

std::string metricsSection(const results::JobResult& job,
                           const std::optional<JobComparison>& compared) {
  if (job.metrics.empty() && job.metrics_full.empty()) return {};
  const bool full = job.full_reference.has_value() || !job.metrics_full.empty();
  std::vector<std::string> names;
  for (const auto& [name, value] : job.metrics) names.push_back(name);
  for (const auto& [name, value] : job.metrics_full)
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);

  std::vector<TableColumn> columns = {
      {"metric"},
      {fmt::format("against the reference of its class ({})", job.reference.path_class), true}};
  if (full) columns.push_back({"against the full reference (all paths)", true});
  if (compared) columns.push_back({"previous run", true});
  HtmlTable table(columns);
  auto value_cell = [&](const results::NamedValues& values, const std::string& name,
                        const std::string& change_key) {
    for (const auto& [key, value] : values)
      if (key == name)
        return verdictSpan(formatNumber(value),
                           compared ? compared->findMetric(change_key) : nullptr);
    return std::string();
  };
  for (const std::string& name : names) {
    std::vector<std::string> row = {escapeHtml(name), value_cell(job.metrics, name, name)};
    if (full) row.push_back(value_cell(job.metrics_full, name, "full:" + name));
    if (compared) {
      const results::MetricChange* change = compared->findMetric(name);
      row.push_back(change ? formatNumber(change->base) : std::string());
    }
    table.addRow(row);
  }
  const std::string note =
      "<p class=\"muted\">Against the reference of the technique's own path class: its "
      "approximation error; against the full reference: also what the class leaves out." +
      std::string(compared ? " Coloured against the previous run (red: worse beyond tolerance, "
                             "green: better)."
                           : "") +
      "</p>\n";
  return htmlSection("metrics", "Metrics", note + table.html());
}

std::string paperSection(const results::RunResults& results, const results::JobResult& job) {
  const std::string table = paperTable(results, &job.id);
  if (table.empty()) return {};
  return htmlSection("paper", "The paper's numbers beside ours", table);
}

}  // namespace

std::string jobPage(const std::filesystem::path& run_dir, const results::RunResults& results,
                    const results::JobResult& job, const RunComparison& comparison,
                    const ReportContext& context) {
  const std::optional<JobComparison> compared = comparison.job(job.id);
  std::string body = fmt::format(
      "<p><a href=\"../index.html\">← {} report</a></p>\n<h1>{}</h1>\n<p class=\"muted\">{} · "
      "{} · run {}</p>\n",
      escapeHtml(results.run.suite), escapeHtml(job.id), escapeHtml(job.scene),
      escapeHtml(job.technique), escapeHtml(results.run.id));
  body += failureSection(job);
  body += jobFacts(job);
  body += metricsSection(job, compared);
  body += htmlSection("images", "Images", imageViewer(run_dir, job));
  if (const std::string aux = auxiliaryImages(run_dir, job); !aux.empty())
    body += htmlSection("auxiliary", "The technique's internal state", aux);
  body += timingsSection(job, compared);
  body += iterationTimingsSection(job);
  body += convergenceSection(job, results.primary_metric);
  body += paperSection(results, job);
  body += trendsSection(results, job, context);
  return htmlPage(fmt::format("{}: {}", job.id, results.run.suite), body);
}

}  // namespace gib::reports
