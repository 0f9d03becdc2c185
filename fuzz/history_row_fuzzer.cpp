// History-database rows as `gibench history`, `diff` and `report` read them back
// (results/history_db.h). A database file holds rows written by other gibench versions and
// machines, so every column is outside input. The input is one run's columns separated by the
// byte 0x1f (unit separator), in this order:
//   results_json, id, suite, started, git_commit, git_dirty, host, gl_renderer,
//   job, scene, technique, frame_ms, metric, value
// Missing trailing fields are empty; a numeric column gets the text when it does not parse (SQLite
// keeps what it is given).
#include "fuzz/fuzz_support.h"
#include "results/history_db.h"
#include "results/sqlite_connection.h"

#include <string>
#include <vector>

namespace {

std::vector<std::string> fields(const std::string& text, std::size_t count) {
  std::vector<std::string> out;
  std::size_t begin = 0;
  while (out.size() + 1 < count) {
    const std::size_t end = text.find('\x1f', begin);
    if (end == std::string::npos) break;
    out.push_back(text.substr(begin, end - begin));
    begin = end + 1;
  }
  out.push_back(begin <= text.size() ? text.substr(begin) : std::string());
  out.resize(count);
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gib;
  using results::detail::SqliteConnection;
  static const std::filesystem::path db_path = fuzz::workDirectory() / "history.sqlite";
  static results::HistoryDatabase history = results::HistoryDatabase::open(db_path);
  // The rows are rewritten for every input: without the disk syncs, thousands a second.
  static SqliteConnection raw(db_path, 1000);
  static const bool unsynced =
      (raw.execute("PRAGMA synchronous = OFF; PRAGMA journal_mode = MEMORY;"), true);
  (void)unsynced;

  const std::vector<std::string> f = fields(fuzz::inputText(data, size), 14);
  raw.execute("BEGIN; DELETE FROM metric_values; DELETE FROM jobs; DELETE FROM runs;");
  raw.prepare(
         "INSERT INTO runs (row, results_json, id, suite, started, finished, git_commit, "
         "git_dirty, host, gl_renderer, gibench_version) "
         "VALUES (1, ?, ?, ?, ?, ?, ?, ?, ?, ?, '0')")
      .bind(1, f[0])
      .bind(2, f[1])
      .bind(3, f[2])
      .bind(4, f[3])
      .bind(5, f[3])
      .bind(6, f[4])
      .bind(7, f[5])
      .bind(8, f[6])
      .bind(9, f[7])
      .run();
  raw.prepare(
         "INSERT INTO jobs (run, job, scene, technique, frame_ms, seconds, reference_key) "
         "VALUES (1, ?, ?, ?, ?, ?, 'key')")
      .bind(1, f[8])
      .bind(2, f[9])
      .bind(3, f[10])
      .bind(4, f[11])
      .bind(5, f[11])
      .run();
  raw.prepare(
         "INSERT INTO metric_values (run, job, scene, technique, metric, value) "
         "VALUES (1, ?, ?, ?, ?, ?)")
      .bind(1, f[8])
      .bind(2, f[9])
      .bind(3, f[10])
      .bind(4, f[12])
      .bind(5, f[13])
      .run();
  raw.execute("COMMIT");

  fuzz::refusedOnlyAsInputError([&] { history.run(std::int64_t{1}); });
  fuzz::refusedOnlyAsInputError([&] { history.run(f[1]); });
  fuzz::refusedOnlyAsInputError([&] { history.runs({}); });
  fuzz::refusedOnlyAsInputError([&] {
    results::HistoryFilter filter;
    filter.metric = f[12];
    filter.since = f[3];
    history.values(filter);
  });
  fuzz::refusedOnlyAsInputError([&] { history.recentRuns(f[2], f[3], 4); });
  fuzz::refusedOnlyAsInputError([&] { history.previousRun(f[2], "9999"); });
  fuzz::refusedOnlyAsInputError([&] { history.referenceKeys(); });
  return 0;
}
