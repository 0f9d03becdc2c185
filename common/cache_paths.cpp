#include "common/cache_paths.h"

#include <cstdlib>

namespace gib {

namespace {

const char* nonEmptyEnvironment(const char* name) {
  const char* value = std::getenv(name);
  return value && *value ? value : nullptr;
}

}  // namespace

std::filesystem::path defaultStoreRoot() {
  if (const char* store = nonEmptyEnvironment("GIBENCH_STORE")) return store;
  if (const char* cache = nonEmptyEnvironment("XDG_CACHE_HOME"))
    return std::filesystem::path(cache) / "gibench";
  if (const char* home = nonEmptyEnvironment("HOME"))
    return std::filesystem::path(home) / ".cache" / "gibench";
  return ".gibench-cache";
}

std::filesystem::path historyDatabasePath(const std::filesystem::path& store_root) {
  return store_root / "history.sqlite";
}

}  // namespace gib
