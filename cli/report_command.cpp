// gibench report RESULTS_DIR [--db FILE] [--store DIR] [--trend-runs N] [--junit FILE.xml]
//                            [--summary FILE.md]
// (Re)builds the HTML report of a run directory from its results.json, coloured against the
// suite's previous run and with trends from the history database when there is one (--db, else
// that of --store, else that of the store the run used).
#include "cli/ci_outputs.h"
#include "cli/commands.h"
#include "cli/history_location.h"
#include "common/input_error.h"
#include "reports/html_report.h"
#include "reports/report_context.h"
#include "reports/report_labels.h"
#include "results/results_json.h"

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <memory>

namespace gib::cli {

namespace {

namespace fs = std::filesystem;

struct ReportOptions {
  std::string dir;
  HistoryLocation history;
  std::size_t trend_runs = 20;
  CiOutputs ci;
};

void checkRunDirectory(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw InputError(fmt::format(
        "results directory '{}' does not exist; give the --out directory of `gibench run`",
        dir.string()));
  if (!fs::is_regular_file(dir / "results.json", ec))
    throw InputError(fmt::format(
        "'{}' holds no results.json; give the --out directory of a `gibench run`", dir.string()));
}

// The previous run of the suite and its recent runs from the history database: the one chosen
// with --db or --store, else the one of the store the run used. A database the user did not
// choose may be absent (no run recorded yet): the report then compares with nothing.
reports::ReportContext historyContext(const results::RunResults& results, HistoryLocation location,
                                      std::size_t trend_runs) {
  const bool chosen = !location.db.empty() || !location.store.empty();
  if (!chosen) location.store = results.run.store;
  std::error_code ec;
  if (!chosen && !fs::exists(location.path(), ec)) {
    fmt::print(stderr, "gibench: no history database at '{}': nothing to compare with\n",
               location.path().string());
    return {};
  }
  return reports::loadReportContext(location.openExisting(), results, trend_runs);
}

int runReport(const ReportOptions& o) {
  const fs::path dir = o.dir;
  checkRunDirectory(dir);
  o.ci.check();
  const results::RunResults results = results::readResultsFile(dir / "results.json");
  const reports::ReportContext context = historyContext(results, o.history, o.trend_runs);
  const fs::path index = reports::writeHtmlReport(dir, results, context);
  o.ci.write(dir, results, context);
  // stdout stays the path alone, for scripts; the address a browser needs (a bare path loses a
  // "#…" view in Chromium) goes to the reader on stderr.
  fmt::print("{}\n", index.string());
  std::fflush(stdout);  // the path before the address when both go to one terminal or file
  fmt::print(stderr, "open       {}\n", reports::fileUrl(index));  // as `gibench run` ends
  return 0;
}

}  // namespace

CommandRunner addReportCommand(CLI::App& app) {
  CLI::App* report = app.add_subcommand(
      "report",
      "(Re)build the HTML report of a run directory, compared with the suite's earlier runs in the "
      "history database (--db, else that of --store, else that of the store the run used)");
  auto o = std::make_shared<ReportOptions>();
  report->add_option("RESULTS_DIR", o->dir, "run directory holding results.json")->required();
  // Without either: the database of the store the run used.
  o->history.addOptions(*report);
  report->add_option("--trend-runs", o->trend_runs, "runs shown in trend charts")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t(1), std::size_t(1000)));
  o->ci.addOptions(*report);
  return [o] { return runReport(*o); };
}

}  // namespace gib::cli
