#include "reports/job_page.h"

#include "common/join.h"

#include "reports/html_text.h"
#include "reports/image_viewer.h"
#include "reports/job_charts.h"
#include "reports/metric_labels.h"
#include "reports/number_format.h"
#include "reports/paper_table.h"
#include "reports/report_labels.h"
#include "reports/report_page.h"
#include "reports/timing_sections.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace gib::reports {

namespace {

namespace fs = std::filesystem;

std::string referenceText(const results::ReferenceUse& use) {
  return fmt::format("{}: {} spp, seed {}, {}; {}", use.key, use.spp, use.seed, referenceLabel(use),
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
      {"compares", checkpointComparisonText(job)},
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

// The heading of the class metrics' column: what they measure the job's image against.
std::string classColumnHeading(const results::JobResult& job) {
  const std::string checkpoint = checkpointComparisonText(job);
  if (!checkpoint.empty())
    return fmt::format("{} ({})", checkpoint, pixelSamplingText(job.reference.pixel_sampling));
  return fmt::format("against the reference of its class ({})", referenceLabel(job.reference));
}

std::string fullColumnHeading(const results::JobResult& job) {
  return fmt::format("against the full reference ({})",
                     job.full_reference ? referenceLabel(*job.full_reference) : "all paths");
}

// What the metrics measure: a technique's error, or a reference job's checkpoint's distance.
std::string metricsNote(const results::JobResult& job) {
  if (!checkpointComparisonText(job).empty())
    return "An independent render to the last convergence checkpoint against the stored "
           "reference: how far that many samples per pixel are from it.";
  return "Against the reference of the technique's own path class: its approximation error; "
         "against the full reference: also what the class leaves out.";
}

std::string metricsSection(const results::JobResult& job,
                           const std::optional<JobComparison>& compared) {
  if (job.metrics.empty() && job.metrics_full.empty()) return {};
  const bool full = job.full_reference.has_value() || !job.metrics_full.empty();
  std::vector<std::string> names;
  for (const auto& [name, value] : job.metrics) names.push_back(name);
  for (const auto& [name, value] : job.metrics_full)
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);

  std::vector<TableColumn> columns = {{"metric"}, {classColumnHeading(job), true}};
  if (full) columns.push_back({fullColumnHeading(job), true});
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
    std::vector<std::string> row = {metricLabelHtml(name), value_cell(job.metrics, name, name)};
    if (full) row.push_back(value_cell(job.metrics_full, name, "full:" + name));
    if (compared) {
      const results::MetricChange* change = compared->findMetric(name);
      row.push_back(change ? formatNumber(change->base) : std::string());
    }
    table.addRow(row);
  }
  const std::string note = "<p class=\"muted\">" + metricsNote(job) +
                           " The reference's pixel sampling: " +
                           escapeHtml(pixelSamplingText(job.reference.pixel_sampling)) + "." +
                           (compared ? " Coloured against the previous run (red: worse beyond "
                                       "tolerance, green: better)."
                                     : "") +
                           "</p>\n";
  return htmlSection("metrics", "Metrics", note + table.html() + metricLegend(names));
}

// The full-precision files behind what the page shows, linked so that a reader can measure them
// again; only files that are there.
std::string filesSection(const fs::path& run_dir, const results::JobResult& job) {
  const std::pair<std::string, std::string> files[] = {
      {job.outputs.image, "the job's image (EXR)"},
      {job.outputs.reference_exr, "the reference of its class (EXR)"},
      {job.outputs.full_reference_exr, "the full reference (EXR)"},
      {"results.json", "the run's results"},
      {job.outputs.timings_json, "every frame's per-pass timings"},
  };
  std::string items;
  for (const auto& [path, what] : files)
    if (outputPresent(run_dir, path))
      items += fmt::format("<li><a href=\"{}\">{}</a>: {}</li>\n", escapeHtml(outputHref(path, 1)),
                           escapeHtml(fs::path(path).filename().string()), escapeHtml(what));
  if (items.empty()) return {};
  return htmlSection("files", "Full-precision files", "<ul class=\"files\">\n" + items + "</ul>\n");
}

// Where the rasteriser and the reference's camera rays hit different surfaces: those pixels'
// error is geometry, not lighting.
std::string disagreementSection(const fs::path& run_dir, const results::JobResult& job) {
  // A mask of no pixel is a black picture: the count says it.
  const bool mask =
      job.disagreement_pixels != 0 && outputPresent(run_dir, job.outputs.disagreement_png);
  if (job.disagreement_pixels < 0 && !mask) return {};
  std::string html = "<p>";
  if (job.disagreement_pixels >= 0) {
    const double pixels = double(job.width) * double(job.height);
    html += fmt::format("<strong>{}</strong> pixel{}", job.disagreement_pixels,
                        job.disagreement_pixels == 1 ? "" : "s");
    if (pixels > 0)
      html += fmt::format(" ({})", formatShare(double(job.disagreement_pixels) / pixels));
    html +=
        " whose primary hit differs between the rasteriser and the reference's camera rays "
        "through the pixel centres (silhouettes, shared edges): their error is geometry, not "
        "lighting.";
  } else {
    html +=
        "The pixels whose primary hit differs between the rasteriser and the reference's "
        "camera rays (white).";
  }
  html += "</p>\n";
  if (mask)
    html += fmt::format(
        "<img class=\"disagreement\" src=\"{}\" alt=\"Pixels where the rasteriser and the ray "
        "tracer disagree on the primary hit\">\n",
        escapeHtml(outputHref(job.outputs.disagreement_png, 1)));
  return htmlSection("disagreement", "Where rasteriser and ray tracer disagree", html);
}

// The renderer behind the page's timings: the job's own (a run spread over machines may differ
// per job), else the run's.
std::string jobRendererNote(const results::RunResults& results, const results::JobResult& job) {
  if (job.technique == "reference")
    return rendererNote(results.run.gl_renderer,
                        "the run's technique jobs; this reference is path traced on the CPU");
  if (!job.execution.gl_renderer.empty()) return rendererNote(job.execution.gl_renderer);
  return rendererNote(results.run.gl_renderer, "the run's");
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
  body += jobRendererNote(results, job);
  body += failureSection(job);
  body += jobFacts(job);
  body += metricsSection(job, compared);
  body += htmlSection("images", "Images", imageViewer(run_dir, job));
  body += disagreementSection(run_dir, job);
  body += filesSection(run_dir, job);
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
