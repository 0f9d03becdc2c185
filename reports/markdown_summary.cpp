#include "reports/markdown_summary.h"

#include "reports/html_text.h"
#include "reports/number_format.h"
#include "reports/paper_check.h"
#include "reports/regressed_values.h"
#include "reports/report_labels.h"

#include <fmt/format.h>

#include <optional>
#include <utility>
#include <vector>

namespace gib::reports {

namespace {

namespace fs = std::filesystem;

// Text in a Markdown paragraph, list item or table cell (GitHub's and GitLab's flavours): the
// punctuation that could start emphasis, a link, an HTML tag, an entity or a cell boundary is
// backslash-escaped, and line breaks become spaces (a table row is one line).
std::string markdownText(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '\n' || c == '\r') {
      out += ' ';
      continue;
    }
    if (std::string_view("\\`*_[]()<>|#!~&").find(c) != std::string_view::npos) out += '\\';
    out += c;
  }
  return out;
}

std::string plural(std::size_t count, const char* noun) {
  return fmt::format("{} {}{}", count, noun, count == 1 ? "" : "s");
}

std::string tableRow(const std::vector<std::string>& cells) {
  std::string row = "|";
  for (const std::string& cell : cells) row += " " + cell + " |";
  return row + "\n";
}

// A link to a file of the run directory, written as the report's pages write theirs.
std::string fileLink(const std::string& text, const std::string& path) {
  return fmt::format("[{}]({})", markdownText(text), urlPath(path));
}

std::string headline(const results::RunResults& results, const RunComparison& comparison,
                     std::size_t regressed_jobs, std::size_t failed, std::size_t paper_outside) {
  const results::RunInfo& run = results.run;
  std::string text =
      fmt::format("## GI Bench: {}, run {}\n\n", markdownText(run.suite), markdownText(run.id));
  std::vector<std::string> facts = {fmt::format("commit {}", markdownText(shortCommit(run))),
                                    plural(results.jobs.size(), "job")};
  if (comparison.hasPrevious()) {
    const results::DiffReport& diff = *comparison.diff();
    facts.push_back(regressed_jobs == 0
                        ? plural(diff.regressions(), "regression")
                        : fmt::format("**{}** ({})", plural(diff.regressions(), "regression"),
                                      plural(regressed_jobs, "job")));
    facts.push_back(plural(diff.improvements(), "improvement"));
    if (diff.unconfirmed() > 0)
      facts.push_back(fmt::format("{} (not regressions)",
                                  plural(diff.unconfirmed(), "unconfirmed timing change")));
  }
  facts.push_back(fmt::format("{} failed", failed));
  facts.push_back(fmt::format("{} out of tolerance", plural(paper_outside, "paper value")));
  for (std::size_t i = 0; i < facts.size(); ++i) text += (i ? " · " : "") + facts[i];
  text += "\n\n";
  if (!comparison.hasPrevious()) {
    text +=
        "No previous run of this suite in the history: nothing was compared, so no "
        "regressions.\n\n";
    return text;
  }
  const results::RunInfo& previous = *comparison.previousRun();
  const std::string against =
      fmt::format("the previous run {} (commit {})", markdownText(previous.id),
                  markdownText(shortCommit(previous)));
  text += comparison.diff()->regressions() == 0
              ? fmt::format("No regressions against {}.\n\n", against)
              : fmt::format("Compared with {}.\n\n", against);
  return text;
}

std::string regressionsTable(const std::vector<RegressedValue>& regressed) {
  if (regressed.empty()) return {};
  std::string text = "### Regressions\n\n";
  text += tableRow({"job", "quantity", "previous", "this run", "change", "allowed"});
  text += "|---|---|---:|---:|---:|---|\n";
  for (const RegressedValue& v : regressed)
    text += tableRow({markdownText(v.job), markdownText(v.quantity), markdownText(v.previous),
                      markdownText(v.next), markdownText(v.change), markdownText(v.allowed)});
  return text + "\n";
}

std::string failedJobs(const results::RunResults& results) {
  std::string text;
  for (const results::JobResult& job : results.jobs)
    if (job.failed())
      text += fmt::format("- {}: {}\n", markdownText(job.id), markdownText(job.failure));
  return text.empty() ? text : "### Failed jobs\n\n" + text + "\n";
}

std::string paperOutside(const std::vector<PaperCheck>& checks) {
  std::string rows;
  for (const PaperCheck& check : checks) {
    if (check.verdict != PaperVerdict::kOutside) continue;
    const results::PaperValue& p = *check.paper;
    const std::string unit = p.unit.empty() ? "" : " " + p.unit;
    rows += tableRow({markdownText(p.job), markdownText(p.quantity),
                      markdownText(formatNumber(p.value) + unit),
                      markdownText(check.ours ? formatNumber(*check.ours) + unit : "not measured"),
                      markdownText(toleranceLabel(*p.tolerance)), markdownText(p.source)});
  }
  if (rows.empty()) return {};
  return "### Paper values out of tolerance\n\n" +
         tableRow({"job", "quantity", "paper", "ours", "allowed", "source"}) +
         "|---|---|---:|---:|---|---|\n" + rows + "\n";
}

std::string pictures(const std::vector<const results::JobResult*>& regressed_jobs,
                     const fs::path& run_dir) {
  if (regressed_jobs.empty()) return {};
  std::string text = fmt::format(
      "### Pictures of the regressed jobs\n\nPaths are relative to the run directory {}.\n\n",
      markdownText(run_dir.string()));
  for (std::size_t i = 0; i < regressed_jobs.size() && i < kSummaryPictureJobs; ++i) {
    const results::JobResult& job = *regressed_jobs[i];
    text += fmt::format("{}:", fileLink(job.id, jobPageFile(job)));
    for (const auto& [label, path] : {std::pair{"reference", &job.outputs.reference_png},
                                      std::pair{"image", &job.outputs.image_png},
                                      std::pair{"difference", &job.outputs.difference_png}})
      if (!path->empty()) text += fmt::format(" ![{}]({})", label, urlPath(*path));
    text += "\n\n";
  }
  if (regressed_jobs.size() > kSummaryPictureJobs)
    text += fmt::format("The pictures of {} are in the report.\n\n",
                        plural(regressed_jobs.size() - kSummaryPictureJobs, "more regressed job"));
  return text;
}

}  // namespace

std::string markdownSummary(const results::RunResults& results, const RunComparison& comparison,
                            const fs::path& run_dir) {
  const std::vector<RegressedValue> regressed = regressedValues(comparison);
  const std::vector<PaperCheck> paper = checkPaperValues(results);
  std::vector<const results::JobResult*> regressed_jobs;
  std::size_t failed = 0, paper_outside = 0;
  for (const results::JobResult& job : results.jobs) {
    failed += job.failed();
    const std::optional<JobComparison> compared = comparison.job(job.id);
    if (compared && compared->overall == results::Verdict::kRegressed)
      regressed_jobs.push_back(&job);
  }
  // Missing jobs regressed too, though they have no pictures.
  std::size_t missing = 0;
  for (const RegressedValue& v : regressed) missing += v.missing;
  for (const PaperCheck& check : paper) paper_outside += check.verdict == PaperVerdict::kOutside;

  std::string text =
      headline(results, comparison, regressed_jobs.size() + missing, failed, paper_outside);
  text += regressionsTable(regressed);
  text += failedJobs(results);
  text += paperOutside(paper);
  text += pictures(regressed_jobs, run_dir);
  text += fmt::format("The report: {} in the run directory {}.\n",
                      fileLink("index.html", "index.html"), markdownText(run_dir.string()));
  return text;
}

}  // namespace gib::reports
