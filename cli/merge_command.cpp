// gibench merge DIR... [--out DIR] [--store DIR] [--db FILE | --no-history] [--trend-runs N]
//                      [--junit FILE.xml] [--summary FILE.md]
// Assembles the parts of a run (`gibench run --shard`, the tasks of `gibench run --slurm`) into
// the whole: results.json, the CSV, the history row and the report, as a local run writes them.
#include "cli/ci_outputs.h"
#include "cli/commands.h"
#include "cli/run_summary.h"
#include "common/cache_paths.h"
#include "common/input_error.h"
#include "reports/report_labels.h"
#include "suites/slurm_submission.h"
#include "suites/suite_runner.h"

#include <fmt/format.h>

#include <memory>

namespace gib::cli {

namespace {

namespace fs = std::filesystem;

struct MergeCommandOptions {
  std::vector<std::string> dirs;
  std::string out;
  std::string store;
  std::string db;
  bool no_history = false;
  int trend_runs = 20;
  CiOutputs ci;
};

int runMerge(const MergeCommandOptions& o) {
  if (o.no_history && !o.db.empty())
    throw InputError("--db and --no-history contradict each other; give one of them");
  if (o.trend_runs < 2)
    throw InputError(fmt::format("--trend-runs {} draws no trend; give 2 or more", o.trend_runs));
  o.ci.check();
  suites::RunOptions options;
  options.out_dir = o.out;
  options.store_root = o.store.empty() ? defaultStoreRoot() : fs::path(o.store);
  if (!o.no_history)
    options.history_db = o.db.empty() ? historyDatabasePath(options.store_root) : fs::path(o.db);
  options.log_of = suites::slurmLogOf;
  std::vector<fs::path> dirs(o.dirs.begin(), o.dirs.end());
  const suites::RunOutcome outcome = suites::mergeRuns(dirs, options);
  const fs::path report = writeRunReport(outcome, options, o.trend_runs, o.ci);
  printRunSummary(outcome, report, o.ci);
  fmt::print("open       {}\n", reports::fileUrl(report));
  if (outcome.failed > 0) {
    fmt::print(stderr, "gibench: {} of {} jobs failed; the report shows why\n", outcome.failed,
               outcome.results.jobs.size());
    return 1;
  }
  return 0;
}

}  // namespace

CommandRunner addMergeCommand(CLI::App& app) {
  auto o = std::make_shared<MergeCommandOptions>();
  CLI::App* merge = app.add_subcommand(
      "merge",
      "Assemble the parts of a run (--shard, --slurm) into results, history row and report");
  merge->add_option("dirs", o->dirs, "run directories: one shared by every part, or one per shard")
      ->required()
      ->check(CLI::ExistingDirectory);
  merge->add_option("--out", o->out, "the merged run's directory (default: the first DIR)");
  merge->add_option("--store", o->store,
                    "reference store (default $GIBENCH_STORE or ~/.cache/gibench)");
  merge->add_option("--db", o->db, "history database (default <store>/history.sqlite)");
  merge->add_flag("--no-history", o->no_history, "do not record the run in a history database");
  merge->add_option("--trend-runs", o->trend_runs, "runs shown in the report's trend charts");
  o->ci.addOptions(*merge);
  return [o] { return runMerge(*o); };
}

}  // namespace gib::cli
