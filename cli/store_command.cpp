// gibench store list|verify|gc [--store DIR]: the reference store (reference/reference_store.h).
#include "cli/commands.h"
#include "common/cache_paths.h"
#include "common/input_error.h"
#include "common/join.h"
#include "gib/reference_renderer_version.h"
#include "reference/reference_store.h"
#include "reference/reference_store_entry.h"
#include "results/history_db.h"
#include "suites/store_verification.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>

namespace gib::cli {

namespace {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

// Keys are shown by their first 12 hex digits: unique in any store of realistic size, and what
// verify and gc --keep take back as prefixes.
constexpr std::size_t kShortKey = 12;

struct StoreOptions {
  std::string store = defaultStoreRoot().string();
  bool json = false;
  std::vector<std::string> prefixes;  // verify: the entries to verify; gc: --keep
  int spp = 64;
  double significance = 0.01;
  bool allow_few_samples = false;  // verify: measure below kMinVerifySpp
  bool dry_run = false;
};

ref::ReferenceStore openStore(const StoreOptions& o) {
  std::error_code ec;
  if (fs::exists(o.store, ec) && !fs::is_directory(o.store, ec))
    throw InputError(fmt::format("--store '{}' is a file; give the store's directory", o.store));
  return ref::ReferenceStore(o.store);
}

std::string shortKey(const std::string& key) {
  return key.substr(0, kShortKey);
}

double megabytes(std::uint64_t bytes) {
  return double(bytes) / 1e6;
}

// "cloud(albedo=0.8)": the scene with the parameters it was loaded with.
std::string sceneLabel(const ref::StoreEntry& e) {
  if (e.spec.scene_parameters.empty()) return e.scene_name;
  return fmt::format("{}({})", e.scene_name, joinNames(e.spec.scene_parameters, ","));
}

// "cornell 24x24 64 spp", the words that let a person recognise an entry.
std::string describeSpec(const ref::StoreEntry& e) {
  return fmt::format("{} {}x{} {} spp", sceneLabel(e), e.spec.width, e.spec.height, e.spec.spp);
}

// The one key among `keys` that starts with `prefix`; an unknown or ambiguous prefix is an input
// error naming it.
std::string resolveKeyPrefix(const std::vector<std::string>& keys, const std::string& prefix,
                             const std::string& root) {
  std::vector<std::string> matches;
  for (const std::string& key : keys)
    if (key.starts_with(prefix)) matches.push_back(key);
  if (matches.empty())
    throw InputError(fmt::format(
        "no store entry has a key starting with '{}'; `gibench store list --store {}` lists them",
        prefix, root));
  if (matches.size() > 1)
    throw InputError(fmt::format(
        "key prefix '{}' matches {} entries ({}); give more digits", prefix, matches.size(),
        joinNames(matches, ", ", [](const std::string& k) { return shortKey(k); })));
  return matches.front();
}

std::vector<std::string> keysOf(const std::vector<ref::StoreEntry>& entries) {
  std::vector<std::string> keys;
  for (const ref::StoreEntry& e : entries) keys.push_back(e.key);
  return keys;
}

// --- store list ------------------------------------------------------------------------------

ordered_json entryJson(const ref::StoreEntry& e) {
  ordered_json j = ref::entryToJson(e);
  j["dir"] = e.dir.string();
  j["size_bytes"] = e.size_bytes;
  j["current"] = e.current;
  return j;
}

int runList(const StoreOptions& o) {
  const std::vector<ref::StoreEntry> entries = openStore(o).list();
  std::uint64_t total = 0;
  for (const ref::StoreEntry& e : entries) total += e.size_bytes;
  if (o.json) {
    ordered_json j = {{"store", o.store},
                      {"renderer_version", ref::kReferenceRendererVersion},
                      {"count", entries.size()},
                      {"total_bytes", total},
                      {"entries", ordered_json::array()}};
    for (const ref::StoreEntry& e : entries) j["entries"].push_back(entryJson(e));
    fmt::print("{}\n", j.dump());
    return 0;
  }
  std::size_t scene_width = 5, class_width = 10;
  for (const ref::StoreEntry& e : entries) {
    scene_width = std::max(scene_width, sceneLabel(e).size());
    class_width = std::max(class_width, ref::describeReferenceQuantity(e.spec).size());
  }
  fmt::print("{:<12}  {:<{}}  {:>9}  {:>6}  {:>6}  {:<{}}  {:<6}  {:>8}  {}\n", "key", "scene",
             scene_width, "size", "spp", "seed", "path class", class_width, "pixels", "MB",
             "created (UTC)");
  bool any_stale = false;
  for (const ref::StoreEntry& e : entries) {
    std::string created = e.created.substr(0, 19);
    std::replace(created.begin(), created.end(), 'T', ' ');
    fmt::print("{:<12}  {:<{}}  {:>9}  {:>6}  {:>6}  {:<{}}  {:<6}  {:>8.1f}  {}{}\n",
               shortKey(e.key), sceneLabel(e), scene_width,
               fmt::format("{}x{}", e.spec.width, e.spec.height), e.spec.spp, e.spec.seed,
               ref::describeReferenceQuantity(e.spec), class_width,
               ref::pixelSamplingName(e.spec.pixel_sampling), megabytes(e.size_bytes), created,
               e.current ? "" : "  stale");
    any_stale = any_stale || !e.current;
  }
  fmt::print("{} {}, {:.1f} MB in {}\n", entries.size(), entries.size() == 1 ? "entry" : "entries",
             megabytes(total), (fs::path(o.store) / "references").string());
  if (any_stale)
    fmt::print(
        "stale: rendered by another version of the reference renderer (never a hit; `gibench "
        "store gc` removes it once no run uses it)\n");
  return 0;
}

// --- store verify ----------------------------------------------------------------------------

long long minSpp(const StoreOptions& o) {
  return o.allow_few_samples ? 2 : suites::kMinVerifySpp;
}

// A scene that no longer loads (a moved scene file) fails its entry rather than the command.
suites::VerifyResult verifyEntry(const ref::ReferenceStore& store, const ref::StoreEntry& entry,
                                 const StoreOptions& o) {
  try {
    return suites::verifyStoreEntry(store, entry, std::uint32_t(o.spp), o.significance,
                                    /*progress=*/true, minSpp(o));
  } catch (const InputError& e) {
    suites::VerifyResult failed;
    failed.key = entry.key;
    failed.problem = fmt::format("cannot load the scene: {}", e.what());
    return failed;
  }
}

int runVerify(const StoreOptions& o) {
  // Before anything is read: bad settings are one error, not one failure per entry.
  suites::checkVerifySettings(o.spp, o.significance, minSpp(o));
  const ref::ReferenceStore store = openStore(o);
  std::vector<ref::StoreEntry> entries = store.list();
  if (!o.prefixes.empty()) {
    const std::vector<std::string> keys = keysOf(entries);
    std::vector<ref::StoreEntry> chosen;
    for (const std::string& prefix : o.prefixes) {
      const std::string key = resolveKeyPrefix(keys, prefix, o.store);
      chosen.push_back(*std::find_if(entries.begin(), entries.end(),
                                     [&](const ref::StoreEntry& e) { return e.key == key; }));
    }
    entries = std::move(chosen);
  }

  std::size_t failed = 0;
  ordered_json results = ordered_json::array();
  for (const ref::StoreEntry& entry : entries) {
    const suites::VerifyResult r = verifyEntry(store, entry, o);
    failed += !r.passed;
    if (o.json) {
      results.push_back({{"key", r.key},
                         {"scene", entry.scene_name},
                         {"passed", r.passed},
                         {"problem", r.problem},
                         {"tested", r.tested},
                         {"failing", r.failing},
                         {"min_p_value", r.min_p_value},
                         {"seconds", r.seconds}});
      continue;
    }
    fmt::print("{}  {}  {}{}{}{} tested, {} failing, {:.1f} s\n", shortKey(r.key),
               describeSpec(entry), r.passed ? "PASS" : "FAIL ", r.problem, r.passed ? "  " : "; ",
               r.tested, r.failing, r.seconds);
    std::fflush(stdout);  // one line per entry as it finishes, also into a pipe
  }
  if (o.json) {
    fmt::print("{}\n", ordered_json{{"store", o.store},
                                    {"spp", o.spp},
                                    {"significance", o.significance},
                                    {"verified", entries.size()},
                                    {"failed", failed},
                                    {"results", results}}
                           .dump());
  } else {
    fmt::print("{} verified at {} spp, family-wise significance {}: {} passed, {} failed\n",
               entries.size(), o.spp, o.significance, entries.size() - failed, failed);
  }
  return failed == 0 ? 0 : 1;
}

// --- store gc --------------------------------------------------------------------------------

// The keys gc must keep: the entries named by --keep and every reference some run recorded in
// the history database at `history_db` used.
std::set<std::string> keysInUse(const std::vector<std::string>& kept_keys,
                                const fs::path& history_db) {
  std::set<std::string> keys(kept_keys.begin(), kept_keys.end());
  // Opened only when it exists: opening creates a database, and gc must not leave one behind.
  std::error_code ec;
  if (fs::is_regular_file(history_db, ec))
    keys.merge(results::HistoryDatabase::open(history_db).referenceKeys());
  return keys;
}

int runGc(const StoreOptions& o) {
  const ref::ReferenceStore store = openStore(o);
  // Every intact entry is a candidate for removal: resolving --keep against those (rather than
  // list(), which stops at a damaged entry) lets gc clear a store that has damaged entries.
  const ref::GcResult candidates = store.collectGarbage({}, /*dry_run=*/true);
  std::vector<std::string> kept_keys;
  for (const std::string& prefix : o.prefixes)
    kept_keys.push_back(resolveKeyPrefix(keysOf(candidates.removed), prefix, o.store));
  const ref::GcResult gc =
      store.collectGarbage(keysInUse(kept_keys, historyDatabasePath(o.store)), o.dry_run);

  const char* verb = o.dry_run ? "would remove" : "removed";
  for (const ref::StoreEntry& e : gc.removed)
    fmt::print("{}  {}  {}  {:.1f} MB\n", verb, shortKey(e.key), describeSpec(e),
               megabytes(e.size_bytes));
  for (const fs::path& dir : gc.debris)
    fmt::print("{}  {}  (an interrupted or damaged write)\n", verb, dir.filename().string());
  fmt::print("{} {:.1f} MB: {} {}, {} other {}\n", o.dry_run ? "would free" : "freed",
             megabytes(gc.bytes), gc.removed.size(), gc.removed.size() == 1 ? "entry" : "entries",
             gc.debris.size(), gc.debris.size() == 1 ? "directory" : "directories");
  return 0;
}

CLI::App* addStoreSubcommand(CLI::App& store, const char* name, const char* description,
                             StoreOptions& o) {
  CLI::App* sub = store.add_subcommand(name, description);
  sub->add_option("--store", o.store,
                  "the store's directory (default: $GIBENCH_STORE, else the user's cache)")
      ->capture_default_str();
  return sub;
}

}  // namespace

CommandRunner addStoreCommand(CLI::App& app) {
  auto o = std::make_shared<StoreOptions>();
  CLI::App* store = app.add_subcommand("store", "List, verify and clean the reference store");
  store->require_subcommand(1);

  CLI::App* list = addStoreSubcommand(*store, "list", "List the stored references", *o);
  list->add_flag("--json", o->json, "print one JSON object instead of a table");

  CLI::App* verify = addStoreSubcommand(
      *store, "verify", "Z-test stored references against fresh low-spp renders", *o);
  verify->add_option("keys", o->prefixes, "key prefixes of the entries (default: every entry)");
  verify->add_option("--spp", o->spp, "samples per pixel of the fresh render")
      ->capture_default_str();
  verify
      ->add_option("--significance", o->significance,
                   "family-wise significance: the chance that an intact entry fails")
      ->capture_default_str();
  verify->add_flag("--json", o->json, "print one JSON object instead of lines");
  verify->add_flag("--allow-few-samples", o->allow_few_samples,
                   "test below 32 spp on either side, where the significance does not hold (to "
                   "measure that, as scripts/verify-false-failure-rate.sh does)");

  CLI::App* gc = addStoreSubcommand(
      *store, "gc", "Remove entries no run uses and the debris of interrupted writes", *o);
  gc->add_flag("--dry-run", o->dry_run, "print what would be removed, remove nothing");
  gc->add_option("--keep", o->prefixes, "key prefixes of entries to keep as well");

  return [o, list, verify] {
    if (list->parsed()) return runList(*o);
    if (verify->parsed()) return runVerify(*o);
    return runGc(*o);
  };
}

}  // namespace gib::cli
