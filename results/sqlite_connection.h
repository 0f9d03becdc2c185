// Private to gib_reports: a thin RAII layer over the SQLite C API for the history database.
// Every value goes through bound parameters, never into the SQL text.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

struct sqlite3;
struct sqlite3_stmt;

namespace gib::results::detail {

// A prepared statement: bind (1-based, like SQLite), then step through the rows.
class SqliteStatement {
 public:
  SqliteStatement(sqlite3* db, std::string_view sql, const std::filesystem::path& file);
  SqliteStatement(const SqliteStatement&) = delete;
  SqliteStatement& operator=(const SqliteStatement&) = delete;
  ~SqliteStatement();

  SqliteStatement& bind(int index, std::string_view text);
  SqliteStatement& bind(int index, std::int64_t value);
  // NaN is stored as NULL (SQLite has no NaN) and reads back as NaN.
  SqliteStatement& bind(int index, double value);
  SqliteStatement& bindNull(int index);

  // True while a row is available; false when done.
  bool step();
  // Runs a statement that returns no rows.
  void run();
  // Clears the bindings and rewinds, to run the statement again.
  void reset();

  bool isNull(int column) const;  // 0-based, like SQLite
  std::int64_t integer(int column) const;
  double real(int column) const;  // NULL → NaN
  std::string text(int column) const;

 private:
  sqlite3* db_;
  sqlite3_stmt* statement_ = nullptr;
  const std::filesystem::path& file_;
};

class SqliteConnection {
 public:
  // Opens or creates the file. Waits up to `busy_timeout_ms` for another writer's lock (a store
  // on a shared disk is written by several machines).
  SqliteConnection(const std::filesystem::path& file, int busy_timeout_ms);
  SqliteConnection(const SqliteConnection&) = delete;
  SqliteConnection& operator=(const SqliteConnection&) = delete;
  ~SqliteConnection();

  void execute(std::string_view sql);  // one or more statements without parameters or rows
  SqliteStatement prepare(std::string_view sql) const;
  std::int64_t lastInsertRow() const;
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  sqlite3* db_ = nullptr;
};

// BEGIN IMMEDIATE (the write lock up front, so that two writers wait rather than deadlock);
// rolled back unless committed.
class SqliteTransaction {
 public:
  explicit SqliteTransaction(SqliteConnection& connection);
  SqliteTransaction(const SqliteTransaction&) = delete;
  SqliteTransaction& operator=(const SqliteTransaction&) = delete;
  ~SqliteTransaction();
  void commit();

 private:
  SqliteConnection& connection_;
  bool done_ = false;
};

// Throws for a failed SQLite call: a gib::InputError for what the user can fix (not a database,
// damaged, read-only, cannot be opened), std::runtime_error otherwise.
void checkSqlite(int code, sqlite3* db, const std::filesystem::path& file);

}  // namespace gib::results::detail
