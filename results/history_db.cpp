#include "results/history_db.h"

#include "common/input_error.h"
#include "common/stall_point.h"
#include "results/history_filter.h"
#include "results/results_json.h"
#include "results/sqlite_connection.h"

#include <fmt/format.h>

#include <algorithm>

namespace gib::results {

namespace {

namespace fs = std::filesystem;
using detail::SqliteConnection;
using detail::SqliteStatement;

// PRAGMA user_version of the schema below; a file with a larger one is from a newer gibench.
constexpr int kHistorySchemaVersion = 1;
// A store on a shared disk is appended to by several machines: wait for their locks.
constexpr int kBusyTimeoutMs = 30000;

// runs.results_json holds the whole results, so that a run can be rebuilt exactly; the other
// columns and tables are what the queries filter and sort on. Full-reference metric values are
// "full:<name>", the median frame time is "frame_ms" (NULL value: NaN).
constexpr const char* kSchema = R"sql(
CREATE TABLE runs (
  row INTEGER PRIMARY KEY,
  id TEXT NOT NULL UNIQUE,
  suite TEXT NOT NULL,
  started TEXT NOT NULL,
  finished TEXT NOT NULL,
  git_commit TEXT NOT NULL,
  git_dirty INTEGER NOT NULL,
  host TEXT NOT NULL,
  gl_renderer TEXT NOT NULL,
  gibench_version TEXT NOT NULL,
  results_json TEXT NOT NULL);
CREATE INDEX runs_by_suite ON runs (suite, started);
CREATE INDEX runs_by_started ON runs (started);
CREATE TABLE jobs (
  run INTEGER NOT NULL REFERENCES runs (row) ON DELETE CASCADE,
  job TEXT NOT NULL,
  scene TEXT NOT NULL,
  technique TEXT NOT NULL,
  frame_ms REAL,
  seconds REAL,
  reference_key TEXT NOT NULL,
  full_reference_key TEXT,
  PRIMARY KEY (run, job));
CREATE INDEX jobs_by_scene ON jobs (scene, technique);
CREATE INDEX jobs_by_technique ON jobs (technique);
CREATE TABLE metric_values (
  run INTEGER NOT NULL REFERENCES runs (row) ON DELETE CASCADE,
  job TEXT NOT NULL,
  scene TEXT NOT NULL,
  technique TEXT NOT NULL,
  metric TEXT NOT NULL,
  value REAL,
  PRIMARY KEY (run, job, metric));
CREATE INDEX metric_values_by_metric ON metric_values (metric, scene, technique, job);
)sql";

// The columns of a RunSummary, read by readSummary from column `first` on.
constexpr const char* kSummaryColumns =
    "r.row, r.id, r.suite, r.started, r.git_commit, r.git_dirty, r.host, r.gl_renderer, "
    "(SELECT count(*) FROM jobs c WHERE c.run = r.row)";
constexpr int kSummaryColumnCount = 9;

RunSummary readSummary(const SqliteStatement& s, int first) {
  return {s.integer(first),  s.text(first + 1), s.text(first + 2),
          s.text(first + 3), s.text(first + 4), s.integer(first + 5) != 0,
          s.text(first + 6), s.text(first + 7), std::size_t(s.integer(first + 8))};
}

int userVersion(SqliteConnection& db) {
  SqliteStatement s = db.prepare("PRAGMA user_version");
  s.step();
  return int(s.integer(0));
}

// A new file gets the schema; an existing one must be ours and not newer. Inside one
// transaction, so that two machines opening a new shared file do not both create it.
void prepareSchema(SqliteConnection& db) {
  if (userVersion(db) == kHistorySchemaVersion) return;
  detail::SqliteTransaction transaction(db);
  const int version = userVersion(db);
  if (version > kHistorySchemaVersion)
    throw InputError(fmt::format(
        "history database '{}' was written by a newer gibench (schema {}, this one reads {}); "
        "update gibench or choose another --db",
        db.file().string(), version, kHistorySchemaVersion));
  if (version == kHistorySchemaVersion) return;
  SqliteStatement tables = db.prepare("SELECT count(*) FROM sqlite_master");
  tables.step();
  if (version != 0 || tables.integer(0) != 0)
    throw InputError(fmt::format(
        "'{}' is a SQLite database but not a gibench history database; choose another --db",
        db.file().string()));
  db.execute(kSchema);
  db.execute(fmt::format("PRAGMA user_version = {}", kHistorySchemaVersion));
  transaction.commit();
}

void checkUniqueJobIds(const RunResults& results) {
  std::set<std::string> ids;
  for (const JobResult& job : results.jobs)
    if (!ids.insert(job.id).second)
      throw InputError(fmt::format("run {} has two jobs with id '{}'; give every job its own id",
                                   results.run.id, job.id));
}

void insertRun(SqliteConnection& db, const RunResults& results, std::optional<std::int64_t> row) {
  SqliteStatement s = db.prepare(
      "INSERT INTO runs (row, id, suite, started, finished, git_commit, git_dirty, host, "
      "gl_renderer, gibench_version, results_json) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  if (row) s.bind(1, *row);
  const RunInfo& r = results.run;
  s.bind(2, r.id).bind(3, r.suite).bind(4, r.started).bind(5, r.finished).bind(6, r.git_commit);
  s.bind(7, std::int64_t(r.git_dirty)).bind(8, r.host).bind(9, r.gl_renderer);
  s.bind(10, r.gibench_version).bind(11, resultsToJson(results).dump());
  s.run();
}

void insertJobs(SqliteConnection& db, std::int64_t row, const RunResults& results) {
  SqliteStatement job_insert = db.prepare(
      "INSERT INTO jobs (run, job, scene, technique, frame_ms, seconds, reference_key, "
      "full_reference_key) VALUES (?, ?, ?, ?, ?, ?, ?, ?)");
  SqliteStatement value_insert = db.prepare(
      "INSERT OR REPLACE INTO metric_values (run, job, scene, technique, metric, value) "
      "VALUES (?, ?, ?, ?, ?, ?)");
  for (const JobResult& job : results.jobs) {
    const std::optional<double> frame_ms = job.frameMedianMs();
    job_insert.bind(1, row).bind(2, job.id).bind(3, job.scene).bind(4, job.technique);
    if (frame_ms) job_insert.bind(5, *frame_ms);
    job_insert.bind(6, job.seconds).bind(7, job.reference.key);
    if (job.full_reference) job_insert.bind(8, job.full_reference->key);
    job_insert.run();
    job_insert.reset();
    auto insert_value = [&](const std::string& metric, double value) {
      value_insert.bind(1, row).bind(2, job.id).bind(3, job.scene).bind(4, job.technique);
      value_insert.bind(5, metric).bind(6, value);
      value_insert.run();
      value_insert.reset();
    };
    for (const auto& [name, value] : job.metrics) insert_value(name, value);
    for (const auto& [name, value] : job.metrics_full) insert_value("full:" + name, value);
    if (frame_ms) insert_value("frame_ms", *frame_ms);
  }
}

void bindAll(SqliteStatement& s, const std::vector<std::string>& parameters) {
  int index = 1;
  for (const std::string& p : parameters) s.bind(index++, p);
}

}  // namespace

struct HistoryDatabase::Impl {
  explicit Impl(const fs::path& path) : db(path, kBusyTimeoutMs) {}
  SqliteConnection db;

  RunResults parseRun(const std::string& text, std::int64_t row) const {
    const std::string source = fmt::format("{} (run {})", db.file().string(), row);
    nlohmann::ordered_json document;
    try {
      document = nlohmann::ordered_json::parse(text);
    } catch (const nlohmann::ordered_json::exception&) {  // a syntax error or a number overflow
      throw InputError(
          fmt::format("{}: the stored results are not valid JSON; append the run "
                      "again from its results.json",
                      source));
    }
    return resultsFromJson(document, source);
  }

  // The runs a query of (row, results_json) returns, in its order.
  std::vector<RunResults> readRuns(SqliteStatement& s) const {
    std::vector<RunResults> runs;
    while (s.step()) runs.push_back(parseRun(s.text(1), s.integer(0)));
    return runs;
  }
};

HistoryDatabase::HistoryDatabase(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
HistoryDatabase::HistoryDatabase(HistoryDatabase&&) noexcept = default;
HistoryDatabase& HistoryDatabase::operator=(HistoryDatabase&&) noexcept = default;
HistoryDatabase::~HistoryDatabase() = default;

HistoryDatabase HistoryDatabase::open(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw InputError(
        fmt::format("history database '{}' is a directory; give a file (--db)", path.string()));
  if (!path.parent_path().empty()) fs::create_directories(path.parent_path(), ec);
  auto impl = std::make_unique<Impl>(path);
  impl->db.execute("PRAGMA foreign_keys = ON");
  prepareSchema(impl->db);
  return HistoryDatabase(std::move(impl));
}

std::int64_t HistoryDatabase::append(const RunResults& results) {
  checkUniqueJobIds(results);
  SqliteConnection& db = impl_->db;
  detail::SqliteTransaction transaction(db);
  // Replacing keeps the run's row number, so that `gibench diff 12 13` keeps its meaning.
  SqliteStatement existing = db.prepare("SELECT row FROM runs WHERE id = ?");
  existing.bind(1, results.run.id);
  std::optional<std::int64_t> row;
  if (existing.step()) row = existing.integer(0);
  if (row) {
    SqliteStatement remove = db.prepare("DELETE FROM runs WHERE row = ?");  // cascades
    remove.bind(1, *row).run();
  }
  insertRun(db, results, row);
  const std::int64_t inserted = row ? *row : db.lastInsertRow();
  insertJobs(db, inserted, results);
  stallPoint("history-commit");
  transaction.commit();
  return inserted;
}

std::optional<RunResults> HistoryDatabase::run(std::int64_t row) const {
  SqliteStatement s = impl_->db.prepare("SELECT row, results_json FROM runs WHERE row = ?");
  s.bind(1, row);
  std::vector<RunResults> runs = impl_->readRuns(s);
  if (runs.empty()) return std::nullopt;
  return std::move(runs.front());
}

std::optional<RunResults> HistoryDatabase::run(const std::string& id) const {
  SqliteStatement s = impl_->db.prepare("SELECT row, results_json FROM runs WHERE id = ?");
  s.bind(1, id);
  std::vector<RunResults> runs = impl_->readRuns(s);
  if (runs.empty()) return std::nullopt;
  return std::move(runs.front());
}

std::vector<RunSummary> HistoryDatabase::runs(const HistoryFilter& filter) const {
  const detail::SqlCondition condition = detail::runCondition(filter);
  SqliteStatement s = impl_->db.prepare(
      fmt::format("SELECT {} FROM runs r{} ORDER BY r.started DESC, r.row DESC LIMIT ?",
                  kSummaryColumns, condition.where));
  bindAll(s, condition.parameters);
  s.bind(int(condition.parameters.size()) + 1,
         filter.limit ? std::int64_t(filter.limit) : std::int64_t(-1));
  std::vector<RunSummary> runs;
  while (s.step()) runs.push_back(readSummary(s, 0));
  return runs;
}

std::vector<MetricPoint> HistoryDatabase::values(const HistoryFilter& filter) const {
  if (filter.metric.empty())
    throw InputError("no metric chosen; name one (--metric relmse, or frame_ms for frame time)");
  const detail::SqlCondition condition = detail::valueCondition(filter);
  SqliteStatement s = impl_->db.prepare(
      fmt::format("SELECT {}, m.job, m.scene, m.technique, m.metric, m.value FROM metric_values m "
                  "JOIN runs r ON r.row = m.run{} ORDER BY r.started DESC, r.row DESC, m.rowid",
                  kSummaryColumns, condition.where));
  bindAll(s, condition.parameters);
  std::vector<MetricPoint> points;
  std::size_t run_count = 0;
  while (s.step()) {
    MetricPoint point{readSummary(s, 0),
                      s.text(kSummaryColumnCount),
                      s.text(kSummaryColumnCount + 1),
                      s.text(kSummaryColumnCount + 2),
                      s.text(kSummaryColumnCount + 3),
                      s.real(kSummaryColumnCount + 4)};
    // The limit counts runs, so that every value of the newest runs is kept.
    if (points.empty() || points.back().run.row != point.run.row) ++run_count;
    if (filter.limit && run_count > filter.limit) break;
    points.push_back(std::move(point));
  }
  return points;
}

std::optional<RunResults> HistoryDatabase::previousRun(const std::string& suite,
                                                       const std::string& started) const {
  SqliteStatement s = impl_->db.prepare(
      "SELECT row, results_json FROM runs WHERE suite = ? AND started < ? "
      "ORDER BY started DESC, row DESC LIMIT 1");
  s.bind(1, suite).bind(2, started);
  std::vector<RunResults> runs = impl_->readRuns(s);
  if (runs.empty()) return std::nullopt;
  return std::move(runs.front());
}

std::vector<RunResults> HistoryDatabase::recentRuns(const std::string& suite,
                                                    const std::string& up_to_started,
                                                    std::size_t count) const {
  SqliteStatement s = impl_->db.prepare(
      "SELECT row, results_json FROM runs WHERE suite = ? AND started <= ? "
      "ORDER BY started DESC, row DESC LIMIT ?");
  s.bind(1, suite).bind(2, up_to_started).bind(3, std::int64_t(count));
  std::vector<RunResults> runs = impl_->readRuns(s);
  std::reverse(runs.begin(), runs.end());
  return runs;
}

std::set<std::string> HistoryDatabase::referenceKeys() const {
  SqliteStatement s = impl_->db.prepare(
      "SELECT reference_key FROM jobs UNION SELECT full_reference_key FROM jobs "
      "WHERE full_reference_key IS NOT NULL");
  std::set<std::string> keys;
  while (s.step())
    if (!s.text(0).empty()) keys.insert(s.text(0));
  return keys;
}

}  // namespace gib::results
