// Where gibench keeps what outlives a run: the reference store and, beside it, the history
// database. One definition so that `run`, `store`, `diff`, `history` and `report` agree.
#pragma once

#include <filesystem>

namespace gib {

// $GIBENCH_STORE when set, else $XDG_CACHE_HOME/gibench, else $HOME/.cache/gibench, else
// ./.gibench-cache (no home directory: a container, say).
std::filesystem::path defaultStoreRoot();

// The history database of a store root: "<root>/history.sqlite".
std::filesystem::path historyDatabasePath(const std::filesystem::path& store_root);

}  // namespace gib
