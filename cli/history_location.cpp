#include "cli/history_location.h"

#include "common/cache_paths.h"
#include "common/input_error.h"

#include <fmt/format.h>

namespace gib::cli {

void HistoryLocation::addOptions(CLI::App& command) {
  command.add_option("--db", db, "history database file (default: history.sqlite of the store)");
  command.add_option("--store", store,
                     "store root whose history database to use (default: $GIBENCH_STORE, else "
                     "the user's cache directory)");
}

std::filesystem::path HistoryLocation::path() const {
  if (!db.empty()) return db;
  return historyDatabasePath(store.empty() ? defaultStoreRoot() : std::filesystem::path(store));
}

results::HistoryDatabase HistoryLocation::openExisting() const {
  const std::filesystem::path file = path();
  std::error_code ec;
  if (!std::filesystem::exists(file, ec))
    throw InputError(fmt::format(
        "no run has been recorded in '{}' (no history database there); choose one with --db FILE "
        "or --store DIR",
        file.string()));
  return results::HistoryDatabase::open(file);
}

}  // namespace gib::cli
