#include "results/sqlite_connection.h"

#include "common/input_error.h"

#include <fmt/format.h>
#include <sqlite3.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace gib::results::detail {

void checkSqlite(int code, sqlite3* db, const std::filesystem::path& file) {
  if (code == SQLITE_OK || code == SQLITE_ROW || code == SQLITE_DONE) return;
  const std::string message = db ? sqlite3_errmsg(db) : sqlite3_errstr(code);
  switch (code & 0xff) {
    case SQLITE_NOTADB:
      throw InputError(fmt::format(
          "'{}' is not a SQLite database; give a gibench history database (--db) or move the "
          "file away",
          file.string()));
    case SQLITE_CORRUPT:
      throw InputError(fmt::format(
          "history database '{}' is damaged ({}); restore it from a backup or choose another --db",
          file.string(), message));
    case SQLITE_READONLY:
      throw InputError(
          fmt::format("history database '{}' is read-only; make it writable or choose another --db",
                      file.string()));
    case SQLITE_CANTOPEN:
    case SQLITE_PERM:
      throw InputError(fmt::format("cannot open history database '{}' ({}); choose another --db",
                                   file.string(), message));
    case SQLITE_FULL:
    case SQLITE_IOERR:
      // SQLite rolls the transaction back: the file stays as it was before it.
      throw InputError(fmt::format(
          "cannot write history database '{}' ({}; is the disk full?); free space, choose "
          "another --db, or run with --no-history",
          file.string(), message));
    case SQLITE_BUSY:
    case SQLITE_LOCKED:
      throw InputError(fmt::format(
          "history database '{}' stayed locked by another process ({}); run again when it is "
          "done, or choose another --db",
          file.string(), message));
    default:
      throw std::runtime_error(fmt::format("history database '{}': {}", file.string(), message));
  }
}

SqliteStatement::SqliteStatement(sqlite3* db, std::string_view sql,
                                 const std::filesystem::path& file)
    : db_(db), file_(file) {
  checkSqlite(sqlite3_prepare_v2(db, sql.data(), int(sql.size()), &statement_, nullptr), db, file);
}

SqliteStatement::~SqliteStatement() {
  sqlite3_finalize(statement_);
}

SqliteStatement& SqliteStatement::bind(int index, std::string_view text) {
  checkSqlite(sqlite3_bind_text(statement_, index, text.data(), int(text.size()), SQLITE_TRANSIENT),
              db_, file_);
  return *this;
}

SqliteStatement& SqliteStatement::bind(int index, std::int64_t value) {
  checkSqlite(sqlite3_bind_int64(statement_, index, value), db_, file_);
  return *this;
}

SqliteStatement& SqliteStatement::bind(int index, double value) {
  if (std::isnan(value)) return bindNull(index);
  checkSqlite(sqlite3_bind_double(statement_, index, value), db_, file_);
  return *this;
}

SqliteStatement& SqliteStatement::bindNull(int index) {
  checkSqlite(sqlite3_bind_null(statement_, index), db_, file_);
  return *this;
}

bool SqliteStatement::step() {
  const int code = sqlite3_step(statement_);
  checkSqlite(code, db_, file_);
  return code == SQLITE_ROW;
}

void SqliteStatement::run() {
  while (step()) {
  }
}

void SqliteStatement::reset() {
  sqlite3_reset(statement_);
  sqlite3_clear_bindings(statement_);
}

bool SqliteStatement::isNull(int column) const {
  return sqlite3_column_type(statement_, column) == SQLITE_NULL;
}

std::int64_t SqliteStatement::integer(int column) const {
  return sqlite3_column_int64(statement_, column);
}

double SqliteStatement::real(int column) const {
  return isNull(column) ? std::numeric_limits<double>::quiet_NaN()
                        : sqlite3_column_double(statement_, column);
}

std::string SqliteStatement::text(int column) const {
  const auto* bytes = sqlite3_column_text(statement_, column);
  return bytes ? std::string(reinterpret_cast<const char*>(bytes),
                             std::size_t(sqlite3_column_bytes(statement_, column)))
               : std::string();
}

SqliteConnection::SqliteConnection(const std::filesystem::path& file, int busy_timeout_ms)
    : file_(file) {
  const int code =
      sqlite3_open_v2(file.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
  if (code != SQLITE_OK) {
    // The handle exists even on failure (for its message) and must be closed.
    const std::string message = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(code);
    sqlite3_close(db_);
    db_ = nullptr;
    throw InputError(fmt::format("cannot open history database '{}' ({}); choose another --db",
                                 file.string(), message));
  }
  sqlite3_busy_timeout(db_, busy_timeout_ms);
}

SqliteConnection::~SqliteConnection() {
  sqlite3_close(db_);
}

void SqliteConnection::execute(std::string_view sql) {
  const std::string statements(sql);
  checkSqlite(sqlite3_exec(db_, statements.c_str(), nullptr, nullptr, nullptr), db_, file_);
}

SqliteStatement SqliteConnection::prepare(std::string_view sql) const {
  return SqliteStatement(db_, sql, file_);
}

std::int64_t SqliteConnection::lastInsertRow() const {
  return sqlite3_last_insert_rowid(db_);
}

SqliteTransaction::SqliteTransaction(SqliteConnection& connection) : connection_(connection) {
  connection_.execute("BEGIN IMMEDIATE");
}

SqliteTransaction::~SqliteTransaction() {
  if (done_) return;
  try {
    connection_.execute("ROLLBACK");
  } catch (...) {
    // Nothing to do: SQLite rolls back itself when a statement of the transaction failed.
  }
}

void SqliteTransaction::commit() {
  connection_.execute("COMMIT");
  done_ = true;
}

}  // namespace gib::results::detail
