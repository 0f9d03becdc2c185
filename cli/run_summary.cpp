#include "cli/run_summary.h"

#include "reports/html_report.h"
#include "reports/report_context.h"
#include "results/history_db.h"

#include <fmt/format.h>

namespace gib::cli {

namespace fs = std::filesystem;

fs::path writeRunReport(const suites::RunOutcome& outcome, const suites::RunOptions& options,
                        int trend_runs, const CiOutputs& ci) {
  reports::ReportContext context;
  if (!options.history_db.empty())
    context = reports::loadReportContext(results::HistoryDatabase::open(options.history_db),
                                         outcome.results, std::size_t(trend_runs));
  const fs::path index = reports::writeHtmlReport(outcome.run_dir, outcome.results, context);
  ci.write(outcome.run_dir, outcome.results, context);
  return index;
}

void printRunSummary(const suites::RunOutcome& outcome, const fs::path& report,
                     const CiOutputs& ci) {
  const results::RunResults& run = outcome.results;
  const std::string metric = run.primary_metric.empty() ? "metric" : run.primary_metric;
  fmt::print("{:<44} {:>12} {:>12} {:>10} {:>8}\n", "job", metric, "full " + metric, "frame ms",
             "seconds");
  for (const results::JobResult& job : run.jobs) {
    if (job.failed()) {
      fmt::print("{:<44} failed: {}\n", job.id, job.failure);
      continue;
    }
    auto value = [&](const results::NamedValues& values) {
      for (const auto& [name, v] : values)
        if (name == run.primary_metric) return fmt::format("{:.4g}", v);
      return std::string("-");
    };
    const std::optional<double> frame = job.frameMedianMs();
    fmt::print("{:<44} {:>12} {:>12} {:>10} {:>8.1f}\n", job.id, value(job.metrics),
               value(job.metrics_full), frame ? fmt::format("{:.2f}", *frame) : "-", job.seconds);
  }
  if (outcome.ran > 0 || outcome.failed == 0)
    fmt::print("jobs       {} run, {} finished earlier\n", outcome.ran, outcome.skipped);
  if (outcome.failed > 0) fmt::print("failed     {} jobs (no history row)\n", outcome.failed);
  fmt::print("results    {}\n", outcome.results_file.string());
  if (outcome.history_row > 0) fmt::print("history    run {}\n", outcome.history_row);
  fmt::print("report     {}\n", report.string());
  if (!ci.junit.empty()) fmt::print("junit      {}\n", ci.junit);
  if (!ci.summary.empty()) fmt::print("summary    {}\n", ci.summary);
}

}  // namespace gib::cli
