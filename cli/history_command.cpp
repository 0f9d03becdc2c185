// gibench history [--db FILE] [--store DIR] [--suite S] [--commit C] [--since D] [--until D]
//                 [--scene S] [--technique T] [--job ID] [--metric M] [--limit N] [--json]
// Without --metric: the recorded runs; with it: that metric's values per run and job.
#include "cli/commands.h"
#include "cli/history_location.h"
#include "cli/text_table.h"
#include "results/json_number.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <memory>

namespace gib::cli {

namespace {

using json = nlohmann::ordered_json;

struct HistoryOptions {
  HistoryLocation location;
  results::HistoryFilter filter;
  bool json = false;
};

// A commit as people quote it: the first 12 hex digits, marked when the build was dirty.
std::string shortCommit(const results::RunSummary& run) {
  return run.git_commit.substr(0, 12) + (run.git_dirty ? "+dirty" : "");
}

json summaryJson(const results::RunSummary& run) {
  return {{"row", run.row},
          {"id", run.id},
          {"suite", run.suite},
          {"started", run.started},
          {"git_commit", run.git_commit},
          {"git_dirty", run.git_dirty},
          {"host", run.host},
          {"gl_renderer", run.gl_renderer},
          {"jobs", run.jobs}};
}

void printRuns(const std::vector<results::RunSummary>& runs, const HistoryOptions& o) {
  if (o.json) {
    json list = json::array();
    for (const results::RunSummary& run : runs) list.push_back(summaryJson(run));
    fmt::print("{}\n", json{{"database", o.location.path().string()}, {"runs", list}}.dump());
    return;
  }
  std::vector<std::vector<std::string>> rows;
  for (const results::RunSummary& run : runs)
    rows.push_back({std::to_string(run.row), run.id, run.suite, run.started, shortCommit(run),
                    run.host, run.gl_renderer.empty() ? "-" : run.gl_renderer,
                    std::to_string(run.jobs)});
  fmt::print(
      "{}",
      formatTable({"row", "id", "suite", "started", "commit", "host", "renderer", "jobs"}, rows));
  if (runs.empty()) fmt::print("no recorded run matches\n");
}

void printValues(const std::vector<results::MetricPoint>& points, const HistoryOptions& o) {
  if (o.json) {
    json list = json::array();
    for (const results::MetricPoint& p : points) {
      json entry = summaryJson(p.run);
      entry.erase("jobs");
      entry.update(json{{"job", p.job},
                        {"scene", p.scene},
                        {"technique", p.technique},
                        {"value", results::numberToJson(p.value)}});
      list.push_back(std::move(entry));
    }
    fmt::print("{}\n", json{{"database", o.location.path().string()},
                            {"metric", o.filter.metric},
                            {"values", list}}
                           .dump());
    return;
  }
  std::vector<std::vector<std::string>> rows;
  for (const results::MetricPoint& p : points)
    rows.push_back({std::to_string(p.run.row), p.run.started, shortCommit(p.run), p.job,
                    fmt::format("{:.6g}", p.value)});
  fmt::print("{}", formatTable({"row", "started", "commit", "job", o.filter.metric}, rows));
  if (points.empty()) fmt::print("no recorded value matches\n");
}

int runHistory(const HistoryOptions& o) {
  const results::HistoryDatabase db = o.location.openExisting();
  if (o.filter.metric.empty())
    printRuns(db.runs(o.filter), o);
  else
    printValues(db.values(o.filter), o);
  return 0;
}

}  // namespace

CommandRunner addHistoryCommand(CLI::App& app) {
  auto o = std::make_shared<HistoryOptions>();
  results::HistoryFilter& f = o->filter;
  CLI::App* history = app.add_subcommand(
      "history", "List recorded runs, or a metric's values across runs, from the history database");
  o->location.addOptions(*history);
  history->add_option("--suite", f.suite, "only runs of this suite");
  history->add_option("--commit", f.commit, "only runs built from commits starting with this");
  history->add_option("--since", f.since,
                      "only runs started on or after (2026-11-22 or "
                      "2026-11-22T10:04:05Z, UTC)");
  history->add_option("--until", f.until, "only runs started on or before (inclusive)");
  history->add_option("--scene", f.scene, "only runs (values) of jobs on this scene");
  history->add_option("--technique", f.technique, "only runs (values) of jobs of this technique");
  history->add_option("--job", f.job, "only runs (values) of this job id");
  history->add_option("--metric", f.metric,
                      "list this metric's values instead of runs (relmse, full:relmse, frame_ms…)");
  history->add_option("--limit", f.limit, "only the newest N runs (0: all)")
      ->check(CLI::NonNegativeNumber);
  history->add_flag("--json", o->json, "print one JSON object instead of a table");
  return [o] { return runHistory(*o); };
}

}  // namespace gib::cli
