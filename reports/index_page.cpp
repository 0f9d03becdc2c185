#include "reports/index_page.h"

#include "reports/figure_charts.h"

#include "reports/html_text.h"
#include "reports/metric_labels.h"
#include "reports/number_format.h"
#include "reports/report_labels.h"
#include "reports/report_page.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <set>

namespace gib::reports {

namespace {

namespace fs = std::filesystem;

// A picture of the index (one directory level: paths as they are), or nothing when the file is
// not there.
std::string thumbnail(const fs::path& run_dir, const std::string& path, const std::string& alt,
                      const char* css_class = "thumb") {
  if (!outputPresent(run_dir, path)) return {};
  return fmt::format("<img class=\"{}\" src=\"{}\" alt=\"{}\" decoding=\"async\">", css_class,
                     escapeHtml(outputHref(path, 0)), escapeHtml(alt));
}

// The job's small picture: its thumbnail, else (a run written before thumbnails) its image.
std::string jobThumbnail(const fs::path& run_dir, const results::JobResult& job) {
  const std::string& path =
      !job.outputs.thumbnail_png.empty() ? job.outputs.thumbnail_png : job.outputs.image_png;
  return thumbnail(run_dir, path, "Image of " + job.id);
}

std::string runFacts(const results::RunInfo& run) {
  const std::string gl = run.gl_renderer.empty() ? std::string()
                                                 : fmt::format("{} ({}, {})", run.gl_renderer,
                                                               run.gl_vendor, run.gl_version);
  return factsTable({
      {"suite", run.suite},
      {"description", run.suite_description},
      {"suite file", run.suite_file},
      {"run", run.id},
      {"started", run.started},
      {"finished", run.finished},
      {"commit", run.git_commit.empty()
                     ? std::string("unknown")
                     : run.git_commit + (run.git_dirty ? " (with uncommitted changes)" : "")},
      {"version", run.gibench_version},
      {"build type", run.build_type},
      {"host", run.host},
      {"CPU", run.cpu_cores > 0 ? fmt::format("{} ({} cores)", run.cpu, run.cpu_cores) : run.cpu},
      {"GL renderer", gl},
      {"Embree", run.embree_version},
      {"parallel jobs", fmt::format("{}", run.parallel_jobs)},
      {"reference store", run.store},
      {"complete", run.complete ? "yes" : "no: some jobs of the suite were left out (--only)"},
      {"conditions", conditionsText(run.conditions)},
  });
}

std::string comparisonIntro(const RunComparison& comparison) {
  if (!comparison.hasPrevious())
    return "<p class=\"note\">No previous run of this suite in the history: nothing is "
           "coloured.</p>\n";
  const results::RunInfo& previous = *comparison.previousRun();
  const results::DiffReport& diff = *comparison.diff();
  return fmt::format(
      "<p>Compared with the previous run <strong>{}</strong> (commit {}, started {}): {} "
      "regression{}, {} improvement{}, {} unconfirmed timing change{}.</p>\n"
      "<p class=\"legend\"><span class=\"verdict-regressed\">worse beyond tolerance</span>"
      "<span class=\"verdict-improved\">better beyond tolerance</span>"
      "<span class=\"verdict-unconfirmed\">a timing beyond tolerance that noise may explain"
      "</span><span class=\"verdict-unchanged\">within tolerance, or new</span></p>\n",
      escapeHtml(previous.id), escapeHtml(shortCommit(previous)), escapeHtml(previous.started),
      diff.regressions(), diff.regressions() == 1 ? "" : "s", diff.improvements(),
      diff.improvements() == 1 ? "" : "s", diff.unconfirmed(), diff.unconfirmed() == 1 ? "" : "s");
}

std::string jobLink(const results::RunResults& results, const std::string& id) {
  const results::JobResult* job = results.findJob(id);
  if (!job) return escapeHtml(id);  // a job of the previous run only
  return fmt::format("<a href=\"{}\">{}</a>", escapeHtml(urlPath(jobPageFile(*job))),
                     escapeHtml(id));
}

std::string toleranceText(const results::Tolerance& t) {
  return fmt::format("±max({}, {}·|previous|)", formatNumber(t.absolute), formatNumber(t.relative));
}

std::string regressionsSection(const fs::path& run_dir, const results::RunResults& results,
                               const RunComparison& comparison) {
  if (!comparison.hasPrevious()) return {};
  const results::DiffReport& diff = *comparison.diff();
  HtmlTable table({{"job"},
                   {"quantity"},
                   {"previous", true},
                   {"this run", true},
                   {"change", true},
                   {"allowed"}});
  for (const results::MetricChange& c : diff.metrics)
    if (c.verdict == results::Verdict::kRegressed)
      table.addRow({jobLink(results, c.job), escapeHtml(c.metric), formatNumber(c.base),
                    formatNumber(c.next), formatChange(c.relative_change),
                    escapeHtml(toleranceText(c.tolerance))});
  for (const results::TimingChange& c : diff.timings)
    if (c.verdict == results::Verdict::kRegressed)
      table.addRow(
          {jobLink(results, c.job), "median frame time (ms)", formatNumber(c.base_median_ms),
           formatNumber(c.next_median_ms), formatChange(c.relative_change),
           escapeHtml(fmt::format("+{}; {}", formatShare(c.tolerance.relative), c.explanation()))});
  for (const results::JobPresence& p : diff.presence)
    if (p.verdict == results::Verdict::kMissing)
      table.addRow({escapeHtml(p.job), "the job", "ran", "missing", "", ""});
  if (table.empty()) return {};
  // Like a render-test report: each regressed job's reference, image and difference side by side.
  std::set<std::string> shown;
  std::string pictures;
  const auto picture = [&](const results::JobResult& job, const std::string& path,
                           const char* caption) {
    const std::string img = thumbnail(run_dir, path, std::string(caption) + " of " + job.id);
    return img.empty()
               ? std::string()
               : fmt::format("<figure>{}<figcaption>{}</figcaption></figure>", img, caption);
  };
  const auto add = [&](const std::string& id) {
    const results::JobResult* job = results.findJob(id);
    if (!job || !shown.insert(id).second) return;
    pictures += fmt::format(
        "<div class=\"regressed-job\"><div>{}</div><div class=\"thumbs\">{}{}{}</div></div>\n",
        jobLink(results, id), picture(*job, job->outputs.reference_png, "reference"),
        picture(*job, job->outputs.image_png, "image"),
        picture(*job, job->outputs.difference_png, "difference"));
  };
  for (const results::MetricChange& c : diff.metrics)
    if (c.verdict == results::Verdict::kRegressed) add(c.job);
  for (const results::TimingChange& c : diff.timings)
    if (c.verdict == results::Verdict::kRegressed) add(c.job);
  return htmlSection("regressions", "Regressions", pictures + table.html());
}

// Scenes in suite order; techniques with the reference first, then in suite order.
std::vector<std::string> orderedUnique(const std::vector<results::JobResult>& jobs,
                                       std::string results::JobResult::*field,
                                       const std::string& first) {
  std::vector<std::string> names;
  if (!first.empty() && std::any_of(jobs.begin(), jobs.end(), [&](const results::JobResult& job) {
        return job.*field == first;
      }))
    names.push_back(first);
  for (const results::JobResult& job : jobs)
    if (std::find(names.begin(), names.end(), job.*field) == names.end())
      names.push_back(job.*field);
  return names;
}

// What the job's class metrics measure, short: the reference's path class and pixel sampling, or
// for a reference job its checkpoint against the stored reference.
std::string classReferenceLabel(const results::JobResult& job) {
  const std::string checkpoint = checkpointComparisonText(job);
  return checkpoint.empty() ? referenceLabel(job.reference) : checkpoint;
}

// One number of a job with the reference it is measured against beside it: "relmse 0.0021 vs
// LE + LDE, pixel centres".
std::string metricLine(const std::string& metric, double value, const results::MetricChange* change,
                       const std::string& against) {
  return fmt::format("<div>{} {} <span class=\"against\">vs {}</span></div>",
                     metricLabelHtml(metric), verdictSpan(formatNumber(value), change),
                     escapeHtml(against));
}

// The primary metric against the class reference and, when the class is narrower, against the
// full one: what the technique approximates badly, and what it leaves out as well.
std::string metricLines(const results::RunResults& results, const results::JobResult& job,
                        const std::optional<JobComparison>& compared) {
  const std::string& metric = results.primary_metric;
  std::string html;
  if (const std::optional<double> value = results::findValue(job.metrics, metric))
    html += metricLine(metric, *value, compared ? compared->findMetric(metric) : nullptr,
                       classReferenceLabel(job));
  if (const std::optional<double> full = results::findValue(job.metrics_full, metric);
      full && job.full_reference)
    html += metricLine(metric, *full, compared ? compared->findMetric("full:" + metric) : nullptr,
                       "full: " + referenceLabel(*job.full_reference));
  return html;
}

// The frame time, and for an iterative technique its iterations' total time beside it (what the
// frame time leaves out), and the precomputation before either.
std::string timeLines(const results::JobResult& job, const std::optional<JobComparison>& compared) {
  std::string html;
  if (const std::optional<double> frame = job.frameMedianMs()) {
    const std::optional<results::TimingChange> timing = compared ? compared->timing : std::nullopt;
    html += fmt::format("<div>frame {}</div>", verdictSpan(formatMilliseconds(*frame), timing));
  }
  if (job.iterations > 0)
    html += fmt::format("<div>{} it. in {}</div>", job.iterations,
                        escapeHtml(formatMilliseconds(job.iterate_ms)));
  if (job.prepare_ms > 0)
    html += fmt::format("<div>prepare {}</div>", escapeHtml(formatMilliseconds(job.prepare_ms)));
  return html;
}

std::string matrixEntry(const fs::path& run_dir, const results::RunResults& results,
                        const results::JobResult& job, bool name_case,
                        const RunComparison& comparison) {
  const std::optional<JobComparison> compared = comparison.job(job.id);
  std::string label = sweepLabel(job);
  if (name_case || label.empty())
    label = label.empty() ? job.case_name : job.case_name + " " + label;
  std::string html = fmt::format(
      "<div class=\"job {}\"><a href=\"{}\">{}<br>{}</a>",
      verdictClass(compared ? std::optional(compared->overall) : std::nullopt),
      escapeHtml(urlPath(jobPageFile(job))), jobThumbnail(run_dir, job), escapeHtml(label));
  if (job.failed()) html += "<div class=\"failure\">failed</div>";
  return html + metricLines(results, job, compared) + timeLines(job, compared) + "</div>";
}

// What "vs …" beside a number means, and the definition of the metric shown.
std::string matrixLegend(const results::RunResults& results) {
  std::string html =
      "<p class=\"muted\">vs: the reference a number is measured against, by its path class and "
      "where its camera rays sample each pixel. Pixel centres: as the rasteriser samples, so "
      "only the technique's lighting differs; box-filtered over the pixel: an anti-aliased "
      "reference, which also counts the rasteriser's aliasing as error. A reference job's "
      "number measures its last convergence checkpoint against the stored reference.</p>\n";
  if (!results.primary_metric.empty()) html += metricLegend({results.primary_metric});
  return html;
}

std::string matrixSection(const fs::path& run_dir, const results::RunResults& results,
                          const RunComparison& comparison) {
  const std::vector<std::string> scenes =
      orderedUnique(results.jobs, &results::JobResult::scene, "");
  const std::vector<std::string> techniques =
      orderedUnique(results.jobs, &results::JobResult::technique, "reference");
  std::vector<TableColumn> columns = {{"scene"}};
  for (const std::string& technique : techniques) columns.push_back({technique});
  HtmlTable table(columns, "matrix");
  for (const std::string& scene : scenes) {
    // Without a reference job in the run, the row shows the scene's reference beside its name.
    std::string scene_cell = escapeHtml(scene);
    if (std::none_of(results.jobs.begin(), results.jobs.end(), [&](const results::JobResult& j) {
          return j.scene == scene && j.technique == "reference";
        }))
      for (const results::JobResult& job : results.jobs)
        if (job.scene == scene) {
          scene_cell += "<br>" + thumbnail(run_dir, job.outputs.reference_png,
                                           "Reference of " + scene, "thumb reference");
          break;
        }
    std::vector<std::string> cells = {scene_cell};
    for (const std::string& technique : techniques) {
      std::vector<const results::JobResult*> jobs;
      std::set<std::string> cases;
      for (const results::JobResult& job : results.jobs)
        if (job.scene == scene && job.technique == technique) {
          jobs.push_back(&job);
          cases.insert(job.case_name);
        }
      std::string cell;
      for (const results::JobResult* job : jobs)
        cell += matrixEntry(run_dir, results, *job, cases.size() > 1, comparison);
      cells.push_back(cell);
    }
    table.addRow(cells);
  }
  const std::string intro = fmt::format(
      "<p class=\"muted\">Each job: its image, {} against the reference of its path class and, "
      "when that class is narrower, against the full reference; the median frame time, an "
      "iterative technique's iterations and their total time, and the preparation before them; "
      "the change from the previous run in brackets. Follow a job to its images, metrics and "
      "timings.</p>\n",
      escapeHtml(results.primary_metric.empty() ? "the error"
                                                : metricLabel(results.primary_metric)));
  return htmlSection("matrix", "Scenes × techniques", intro + table.html() + matrixLegend(results));
}

}  // namespace

std::string indexPage(const fs::path& run_dir, const results::RunResults& results,
                      const RunComparison& comparison) {
  std::string body = fmt::format("<h1>GI Bench report: {}</h1>\n", escapeHtml(results.run.suite));
  body += rendererNote(results.run.gl_renderer, "the run's technique jobs");
  if (!results.run.suite_description.empty())
    body += fmt::format("<p>{}</p>\n", escapeHtml(results.run.suite_description));
  // Pictures first: what changed, then every job; the run's facts last.
  body += htmlSection("comparison", "Against the previous run", comparisonIntro(comparison));
  body += regressionsSection(run_dir, results, comparison);
  body += matrixSection(run_dir, results, comparison);
  body += figuresSection(run_dir, results);
  body += htmlSection("run", "Run", runFacts(results.run));
  return htmlPage(fmt::format("GI Bench: {} ({})", results.run.suite, results.run.id), body);
}

}  // namespace gib::reports
