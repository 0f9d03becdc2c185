// gibench diff BASE NEW [--json] [--db FILE] [--store DIR]
// Exit 0 when nothing regressed, 1 when something did (so `git bisect run` can drive it), 2 on
// bad input.
#include "cli/commands.h"
#include "cli/history_location.h"
#include "common/input_error.h"
#include "results/results_diff.h"
#include "results/results_json.h"

#include <fmt/format.h>

#include <charconv>
#include <filesystem>
#include <memory>
#include <optional>

namespace gib::cli {

namespace {

namespace fs = std::filesystem;

struct DiffOptions {
  std::string base, next;
  bool json = false;
  HistoryLocation history;
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

int runDiff(const DiffOptions& o) {
  const results::RunResults base = resolveRun(o.base, o.history);
  const results::RunResults next = resolveRun(o.next, o.history);
  const results::DiffReport diff = results::diffResults(base, next);
  if (o.json)
    fmt::print("{}\n", results::diffJson(diff).dump());
  else
    fmt::print("{}", results::formatDiff(diff));
  return diff.regressions() > 0 ? 1 : 0;
}

}  // namespace

CommandRunner addDiffCommand(CLI::App& app) {
  auto o = std::make_shared<DiffOptions>();
  CLI::App* diff = app.add_subcommand(
      "diff", "Compare two runs; exit 1 when the new one regressed (for git bisect run)");
  diff->add_option("base", o->base,
                   "base run: results.json, a run directory, or a run (row number or id) of the "
                   "history database")
      ->required();
  diff->add_option("new", o->next, "new run, in the same forms")->required();
  diff->add_flag("--json", o->json, "print one JSON object instead of a table");
  o->history.addOptions(*diff);
  return [o] { return runDiff(*o); };
}

}  // namespace gib::cli
