// gibench run SUITE.toml [--out DIR] [--store DIR] [--db FILE | --no-history] [--jobs N]
//                        [--only PATTERN ...] [--list] [--gl-device D] [--trend-runs N]
#include "cli/commands.h"
#include "common/cache_paths.h"
#include "common/input_error.h"
#include "common/progress.h"
#include "reports/html_report.h"
#include "reports/report_context.h"
#include "results/history_db.h"
#include "suites/run_environment.h"
#include "suites/suite_file.h"
#include "suites/suite_runner.h"

#include <fmt/format.h>

#include <memory>

namespace gib::cli {

namespace {

namespace fs = std::filesystem;

struct RunCommandOptions {
  std::string suite;
  std::string out;
  std::string store;
  std::string db;
  bool no_history = false;
  int jobs = 1;
  std::vector<std::string> only;
  bool list = false;
  std::string gl_device;
  int trend_runs = 20;
};

// "runs/smoke-20261122-100405": a new directory per run unless --out names one (to resume).
fs::path defaultOutDir(const std::string& suite) {
  std::string stamp;
  for (char c : suites::utcTimestamp())
    if (std::isdigit(static_cast<unsigned char>(c))) stamp += c;
  return fs::path("runs") / fmt::format("{}-{}-{}", suite, stamp.substr(0, 8), stamp.substr(8));
}

// The run's report, compared with the suite's earlier runs in the history database it was
// recorded in (none without one).
fs::path writeReport(const suites::RunOutcome& outcome, const suites::RunOptions& options,
                     int trend_runs) {
  reports::ReportContext context;
  if (!options.history_db.empty())
    context = reports::loadReportContext(results::HistoryDatabase::open(options.history_db),
                                         outcome.results, std::size_t(trend_runs));
  return reports::writeHtmlReport(outcome.run_dir, outcome.results, context);
}

void printSummary(const suites::RunOutcome& outcome, const fs::path& report) {
  const results::RunResults& run = outcome.results;
  const std::string metric = run.primary_metric.empty() ? "metric" : run.primary_metric;
  fmt::print("{:<44} {:>12} {:>12} {:>10} {:>8}\n", "job", metric, "full " + metric, "frame ms",
             "seconds");
  for (const results::JobResult& job : run.jobs) {
    auto value = [&](const results::NamedValues& values) {
      for (const auto& [name, v] : values)
        if (name == run.primary_metric) return fmt::format("{:.4g}", v);
      return std::string("-");
    };
    const std::optional<double> frame = job.frameMedianMs();
    fmt::print("{:<44} {:>12} {:>12} {:>10} {:>8.1f}\n", job.id, value(job.metrics),
               value(job.metrics_full), frame ? fmt::format("{:.2f}", *frame) : "-", job.seconds);
  }
  fmt::print("jobs       {} run, {} finished earlier\n", outcome.ran, outcome.skipped);
  fmt::print("results    {}\n", outcome.results_file.string());
  if (outcome.history_row > 0) fmt::print("history    run {}\n", outcome.history_row);
  fmt::print("report     {}\n", report.string());
}

int runRun(const RunCommandOptions& o) {
  const suites::Suite suite = suites::loadSuiteFile(o.suite);
  if (o.list) {
    for (const suites::Job& job : suites::selectJobs(suite, o.only)) fmt::print("{}\n", job.id);
    return 0;
  }
  if (o.trend_runs < 2)
    throw InputError(fmt::format("--trend-runs {} draws no trend; give 2 or more", o.trend_runs));
  if (o.no_history && !o.db.empty())
    throw InputError("--db and --no-history contradict each other; give one of them");
  suites::RunOptions options;
  options.suite_file = o.suite;
  options.out_dir = o.out.empty() ? defaultOutDir(suite.name) : fs::path(o.out);
  options.store_root = o.store.empty() ? defaultStoreRoot() : fs::path(o.store);
  if (!o.no_history)
    options.history_db = o.db.empty() ? historyDatabasePath(options.store_root) : fs::path(o.db);
  options.parallel_jobs = o.jobs;
  options.only = o.only;
  options.gl_device = o.gl_device;
  options.progress = ProgressBar::stderrIsTerminal();
  const suites::RunOutcome outcome = suites::runSuite(suite, options);
  printSummary(outcome, writeReport(outcome, options, o.trend_runs));
  return 0;
}

}  // namespace

CommandRunner addRunCommand(CLI::App& app) {
  auto o = std::make_shared<RunCommandOptions>();
  CLI::App* run = app.add_subcommand(
      "run", "Run a suite: render, measure and record every job; write results and a report");
  run->add_option("suite", o->suite, "suite file (suites/smoke.toml, suites/nightly.toml, …)")
      ->required();
  run->add_option("--out", o->out,
                  "run directory (default runs/<suite>-<date>-<time>); give an interrupted "
                  "run's directory to resume it");
  run->add_option("--store", o->store,
                  "reference store (default $GIBENCH_STORE or ~/.cache/gibench)");
  run->add_option("--db", o->db, "history database (default <store>/history.sqlite)");
  run->add_flag("--no-history", o->no_history, "do not record the run in a history database");
  run->add_option("--jobs", o->jobs, "jobs at a time (timings are only comparable at 1)");
  run->add_option("--only", o->only, "run only the jobs whose id matches a glob pattern");
  run->add_flag("--list", o->list, "print the job ids (after --only) and exit");
  run->add_option("--gl-device", o->gl_device, "auto | surfaceless | N (EGL device index)");
  run->add_option("--trend-runs", o->trend_runs, "runs shown in the report's trend charts");
  return [o] { return runRun(*o); };
}

}  // namespace gib::cli
