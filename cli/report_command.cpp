// gibench report RESULTS_DIR [--db FILE] [--store DIR] [--trend-runs N]
// (Re)builds the HTML report of a run directory from its results.json, coloured against the
// suite's previous run and with trends from the history database when there is one.
#include "cli/commands.h"
#include "common/cache_paths.h"
#include "common/input_error.h"
#include "reports/html_report.h"
#include "reports/results_json.h"

#include <fmt/format.h>

#include <filesystem>
#include <memory>

namespace gib::cli {

namespace {

namespace fs = std::filesystem;

struct ReportOptions {
  std::string dir;
  std::string db;
  std::string store;
  std::size_t trend_runs = 20;
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

int runReport(const ReportOptions& o) {
  const fs::path dir = o.dir;
  checkRunDirectory(dir);
  const reports::RunResults results = reports::readResultsFile(dir / "results.json");
  const reports::ReportContext context;
  fmt::print("{}\n", reports::writeHtmlReport(dir, results, context).string());
  return 0;
}

}  // namespace

CommandRunner addReportCommand(CLI::App& app) {
  CLI::App* report = app.add_subcommand("report", "(Re)build the HTML report of a run directory");
  auto o = std::make_shared<ReportOptions>();
  report->add_option("RESULTS_DIR", o->dir, "run directory holding results.json")->required();
  report->add_option("--db", o->db,
                     "history database (default: history.sqlite of --store, else of the run's "
                     "store)");
  report->add_option("--store", o->store, "reference store root whose history database to use");
  report->add_option("--trend-runs", o->trend_runs, "runs shown in trend charts")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  return [o] { return runReport(*o); };
}

}  // namespace gib::cli
