// Where `diff` and `history` find the history database: --db FILE, else the database of --store
// DIR, else that of the default store (common/cache_paths.h). Reading commands never create one.
#pragma once

#include "results/history_db.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <string>

namespace gib::cli {

struct HistoryLocation {
  std::string db;
  std::string store;

  // Adds --db and --store to the command.
  void addOptions(CLI::App& command);
  std::filesystem::path path() const;
  // Opens the database for reading; a gib::InputError saying that no run has been recorded
  // there, and how to choose another, when the file does not exist.
  results::HistoryDatabase openExisting() const;
};

}  // namespace gib::cli
