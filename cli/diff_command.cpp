// gibench diff BASE NEW [--json] [--verbose] [--db FILE] [--store DIR] [--history-runs N]
//                      [--strict-timing] [--confirm [--pairs N] [--base-gibench PATH]
//                      [--new-gibench PATH]]
// Exit 0 when nothing regressed, 1 when something did (so `git bisect run` can drive it), 2 on
// bad input, 4 when nothing regressed but --confirm could not confirm a timing (a build could not
// render its job): the diff cannot say "unchanged", and a bisect step skips the commit.
#include "cli/commands.h"
#include "cli/history_location.h"
#include "common/input_error.h"
#include "common/subprocess.h"
#include "gib/version.h"
#include "metrics/timing_statistics.h"
#include "results/results_diff.h"
#include "results/results_json.h"
#include "results/timing_history.h"
#include "suites/timing_confirmation.h"

#include <fmt/format.h>
#include <unistd.h>

#include <charconv>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>

namespace gib::cli {

namespace {

namespace fs = std::filesystem;

struct DiffCommandOptions {
  std::string base, next;
  bool json = false;
  bool verbose = false;
  HistoryLocation history;
  std::size_t history_runs = 30;
  bool strict_timing = false;
  bool confirm = false;
  int pairs = 0;  // 0: metrics::recommendedPairs of the diff's per-comparison significance
  std::string base_gibench, new_gibench;
  std::string gl_device;
};

std::optional<std::int64_t> parseRowNumber(const std::string& text) {
  std::int64_t row = 0;
  const char* end = text.data() + text.size();
  auto [stop, error] = std::from_chars(text.data(), end, row);
  if (error != std::errc() || stop != end) return std::nullopt;
  return row;
}

// A path when it names something on disk or looks like one; otherwise a run of the history
// database, by row number or run id.
results::RunResults resolveRun(const std::string& argument, const HistoryLocation& history) {
  std::error_code ec;
  const bool looks_like_path =
      argument.find('/') != std::string::npos || fs::path(argument).extension() == ".json";
  if (fs::exists(argument, ec) || looks_like_path) return results::readResultsFile(argument);
  if (!fs::exists(history.path(), ec))
    throw InputError(fmt::format(
        "'{}' is not a file, and there is no history database at '{}' to look it up in; give a "
        "results.json or a run directory, or choose the database with --db FILE or --store DIR",
        argument, history.path().string()));
  const results::HistoryDatabase db = history.openExisting();
  const std::optional<std::int64_t> row = parseRowNumber(argument);
  std::optional<results::RunResults> run = row ? db.run(*row) : db.run(argument);
  if (!run)
    throw InputError(fmt::format(
        "'{}' is neither a file nor a run in the history database '{}'; `gibench history` lists "
        "the recorded runs",
        argument, history.path().string()));
  return std::move(*run);
}

// The comparable earlier runs of the history database, when there is one: the run-to-run spread
// each timing is judged against. A database nobody chose may be absent (nothing recorded yet).
results::TimingHistory timingHistory(const DiffCommandOptions& o, const results::RunResults& base,
                                     const results::RunResults& next) {
  std::error_code ec;
  if (!fs::exists(o.history.path(), ec)) return {};
  return results::loadTimingHistory(o.history.openExisting(), base, next, o.history_runs);
}

// The build that made `run`: the given one, else this program when it has the run's version.
fs::path buildOf(const results::RunResults& run, const std::string& given, const char* option) {
  if (!given.empty()) {
    if (access(given.c_str(), X_OK) != 0)
      throw InputError(
          fmt::format("{} '{}' is not an executable; give the gibench of that run's "
                      "build",
                      option, given));
    return given;
  }
  if (run.run.gibench_version == kVersion) return currentExecutable();
  throw InputError(fmt::format(
      "--confirm reruns run {}'s jobs with its own build (gibench {}), and this is {}; give it "
      "with {} PATH",
      run.run.id, run.run.gibench_version, kVersion, option));
}

// The exit code of a diff that found no regression but could not confirm every timing it tried
// to: not 0, since a timing left to the runs alone can hide a slowdown; not 1, since none was
// seen; not 2 or 3, since the input was fine and gibench did not fail.
constexpr int kExitUnconfirmable = 4;

// Settles every timing change worth it by interleaved A/B runs (suites/timing_confirmation.h);
// returns how many could not be (a job one build cannot render), each named on stderr.
std::size_t confirmTimings(results::DiffReport& diff, const results::RunResults& base,
                           const results::RunResults& next, const DiffCommandOptions& o) {
  suites::ConfirmationOptions options;
  options.base_gibench = buildOf(base, o.base_gibench, "--base-gibench");
  options.new_gibench = buildOf(next, o.new_gibench, "--new-gibench");
  options.pairs =
      o.pairs > 0 ? o.pairs : metrics::recommendedPairs(diff.timing_comparison_significance);
  options.gl_device = o.gl_device;
  char pattern[] = "/tmp/gibench-confirm-XXXXXX";
  if (!mkdtemp(pattern)) throw std::runtime_error("cannot make a temporary directory");
  options.work_dir = pattern;
  options.log = [](const std::string& line) { fmt::print(stderr, "{}\n", line); };
  struct Cleanup {
    fs::path dir;
    ~Cleanup() {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  } cleanup{options.work_dir};
  std::size_t failed = 0;
  for (results::TimingChange& change : diff.timings) {
    if (!results::worthConfirming(change)) continue;
    const results::JobResult* base_job = base.findJob(change.job);
    const results::JobResult* next_job = next.findJob(change.job);
    try {
      suites::InterleavedRuns runs = suites::runInterleaved(*base_job, *next_job, options);
      results::confirmTiming(change, std::move(runs.base_ms), std::move(runs.new_ms));
    } catch (const std::runtime_error& e) {
      // A job one build cannot render keeps the verdict it had, with the reason.
      fmt::print(stderr, "gibench: could not confirm {}: {}\n", change.job, e.what());
      ++failed;
    }
  }
  return failed;
}

int runDiff(const DiffCommandOptions& o) {
  const results::RunResults base = resolveRun(o.base, o.history);
  const results::RunResults next = resolveRun(o.next, o.history);
  results::DiffOptions options;
  options.history = timingHistory(o, base, next);
  options.strict_timing = o.strict_timing;
  results::DiffReport diff = results::diffResults(base, next, options);
  const std::size_t unconfirmable = o.confirm ? confirmTimings(diff, base, next, o) : 0;
  if (o.json)
    fmt::print("{}\n", results::diffJson(diff).dump());
  else
    fmt::print("{}", results::formatDiff(diff, o.verbose));
  if (diff.regressions() > 0) return 1;
  return unconfirmable > 0 ? kExitUnconfirmable : 0;
}

}  // namespace

CommandRunner addDiffCommand(CLI::App& app) {
  auto o = std::make_shared<DiffCommandOptions>();
  CLI::App* diff = app.add_subcommand(
      "diff", "Compare two runs; exit 1 when the new one regressed (for git bisect run)");
  diff->add_option("base", o->base,
                   "base run: results.json, a run directory, or a run (row number or id) of the "
                   "history database")
      ->required();
  diff->add_option("new", o->next, "new run, in the same forms")->required();
  diff->add_flag("--json", o->json, "print one JSON object instead of a table");
  diff->add_flag("--verbose", o->verbose, "also list the timings judged unchanged");
  o->history.addOptions(*diff);
  diff->add_option("--history-runs", o->history_runs,
                   "comparable earlier runs of the history whose spread judges timings")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t(1), std::size_t(1000)));
  diff->add_flag("--strict-timing", o->strict_timing,
                 "count an unconfirmed slowdown as a regression");
  CLI::Option* confirm = diff->add_flag(
      "--confirm", o->confirm,
      "settle each changed timing by rendering its job with the base and the new build "
      "alternately on this machine (A B A B …); exit 4 when one could not be confirmed and "
      "nothing regressed");
  diff->add_option("--pairs", o->pairs,
                   "A/B runs of each build per confirmed job (default: enough for its test to "
                   "reach the diff's significance with one outlier and one lost pair: 16 to 21)")
      ->check(CLI::Range(2, 100))
      ->needs(confirm);
  diff->add_option("--base-gibench", o->base_gibench,
                   "the base run's build (default: this gibench, if the base run is its own)")
      ->needs(confirm);
  diff->add_option("--new-gibench", o->new_gibench,
                   "the new run's build (default: this gibench, if the new run is its own)")
      ->needs(confirm);
  diff->add_option("--gl-device", o->gl_device, "auto | surfaceless | N, for the A/B renders")
      ->needs(confirm);
  return [o] { return runDiff(*o); };
}

}  // namespace gib::cli
