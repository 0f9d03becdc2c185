#include "reference/reference_store.h"

#include "common/content_hash.h"
#include "common/input_error.h"
#include "common/stall_point.h"
#include "gib/reference_renderer_version.h"
#include "gib/version.h"
#include "image/exr_io.h"
#include "image/output_files.h"
#include "reference/reference_output.h"
#include "reference/reference_store_entry.h"
#include "reference/reference_store_lock.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <ctime>
#include <thread>

namespace gib::ref {

namespace fs = std::filesystem;

namespace {

// Changed when the key's canonical stream changes, so that old and new keys never collide.
constexpr const char* kKeyFormat = "gibench-reference-key/1";
// Entries are written into "<references>/.tmp-<key>-<pid>-<n>" and renamed into place.
constexpr std::string_view kStagingPrefix = ".tmp-";
// A staging directory is made after the render and lives for the seconds its files take to
// write; one older than this is the debris of an interrupted write, a younger one may belong to a
// process writing right now, so gc leaves it alone.
constexpr auto kDebrisAge = std::chrono::hours(1);

fs::path referencesDir(const fs::path& root) {
  return root / "references";
}

bool isHexKey(const std::string& key) {
  return !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
  });
}

std::string nowIso8601Utc() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
  const auto millis =
      std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  // Milliseconds, so that entries made within one second still list newest first.
  return fmt::format("{:04}-{:02}-{:02}T{:02}:{:02}:{:02}.{:03}Z", utc.tm_year + 1900,
                     utc.tm_mon + 1, utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec, millis);
}

InputError storeNotWritable(const fs::path& root, const std::string& reason) {
  return InputError(
      fmt::format("{}: cannot write the reference store ({}); choose another with --store DIR",
                  root.string(), reason));
}

// A fresh staging directory, removed when this goes out of scope unless released: a failed
// write leaves no debris behind.
class StagingDir {
 public:
  StagingDir(const fs::path& root, const std::string& key) {
    static std::atomic<std::uint64_t> counter{0};
    path_ = referencesDir(root) /
            fmt::format("{}{}-{}-{}", kStagingPrefix, key, getpid(), counter.fetch_add(1));
    std::error_code ec;
    fs::create_directories(path_, ec);
    if (ec) throw storeNotWritable(root, ec.message());
  }
  ~StagingDir() {
    std::error_code ignored;
    if (!path_.empty()) fs::remove_all(path_, ignored);
  }
  StagingDir(const StagingDir&) = delete;
  StagingDir& operator=(const StagingDir&) = delete;

  const fs::path& path() const { return path_; }
  void release() { path_.clear(); }

 private:
  fs::path path_;
};

// The entry in `dir` with its images. Throws gib::InputError when any part is unreadable.
StoredReference loadStored(const fs::path& dir) {
  StoredReference stored;
  stored.entry = readStoreEntry(dir);
  const fs::path exr_path = dir / "reference.exr";
  if (stored.entry.exr_hash.empty())
    throw InputError(
        fmt::format("'{}' was stored by an older gibench without a content hash, so "
                    "it cannot be checked; it is rendered again when needed, and "
                    "`gibench store gc` removes it",
                    exr_path.string()));
  if (hashFileContents(exr_path) != stored.entry.exr_hash)
    throw InputError(
        fmt::format("'{}' does not match the content hash in its entry.json "
                    "(damaged); it is rendered again when needed, and `gibench "
                    "store gc` removes damaged entries",
                    exr_path.string()));
  const image::ExrFile exr = image::readExr(exr_path);
  stored.mean = exr.rgb();
  if (const image::Image* variance = exr.findLayer("variance")) {
    stored.variance = *variance;
    stored.variance_dof = varianceDegreesOfFreedom(exr.metadata);
  }
  if (stored.mean.width() != stored.entry.spec.width ||
      stored.mean.height() != stored.entry.spec.height)
    throw InputError(
        fmt::format("'{}' is {}x{}, not the {}x{} of its entry.json; `gibench store gc` removes "
                    "damaged entries",
                    (dir / "reference.exr").string(), stored.mean.width(), stored.mean.height(),
                    stored.entry.spec.width, stored.entry.spec.height));
  stored.hit = true;
  return stored;
}

// The intact entry in `dir`, if any: a damaged one counts as absent, to be replaced.
std::optional<StoredReference> loadIntact(const fs::path& dir) {
  if (!fs::exists(dir / "entry.json")) return std::nullopt;
  try {
    return loadStored(dir);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

StoreEntry describeEntry(const scene::Scene& scene, const ReferenceSpec& spec,
                         const std::string& key, double render_seconds) {
  StoreEntry entry;
  entry.key = key;
  entry.spec = spec;
  // A scene file is recorded by its absolute path, so that `store verify` finds it from anywhere.
  if (fs::path(spec.scene).extension() == ".toml") entry.spec.scene = fs::absolute(spec.scene);
  entry.scene_name = scene.name;
  entry.scene_hash = scene::hashScene(scene);
  entry.renderer_version = kReferenceRendererVersion;
  entry.gibench_version = kVersion;
  entry.created = nowIso8601Utc();
  entry.render_seconds = render_seconds;
  return entry;
}

// Renames the staging directory to `final_dir`. When another process has published the key
// meanwhile, its entry wins (same inputs, same pixels) and is returned; ours is discarded with
// the staging directory. A damaged entry in the way is replaced.
std::optional<StoredReference> publish(StagingDir& staging, const fs::path& final_dir,
                                       const fs::path& root, const std::string& key) {
  stallPoint("store-entry");
  std::error_code ec;
  fs::rename(staging.path(), final_dir, ec);
  if (!ec) {
    staging.release();
    return std::nullopt;
  }
  if (std::optional<StoredReference> existing = loadIntact(final_dir)) {
    existing->hit = false;  // this call did render; the pixels are the same
    return existing;
  }
  // Step aside: move the damaged entry to a staging name (atomic, so that no reader sees it half
  // removed), remove it, and retry.
  StagingDir damaged(root, key);
  fs::rename(final_dir, damaged.path(), ec);
  fs::rename(staging.path(), final_dir, ec);
  if (ec) throw storeNotWritable(root, ec.message());
  staging.release();
  return std::nullopt;
}

}  // namespace

std::string referenceKey(const scene::Scene& scene, const ReferenceSpec& spec) {
  auto signedValue = [](long long v) { return static_cast<std::uint64_t>(v); };
  ContentHasher hasher;
  hasher.addString(kKeyFormat);
  hasher.addString(scene::hashScene(scene));
  hasher.addU64(signedValue(spec.width));
  hasher.addU64(signedValue(spec.height));
  hasher.addU64(spec.spp);
  hasher.addU64(spec.seed);
  hasher.addU64(signedValue(spec.path_class.min_bounces));
  hasher.addU64(signedValue(spec.path_class.max_bounces));
  // Only for an expression class, so that every key of a class of bounces stays valid.
  if (!spec.path_class.expression.empty()) hasher.addString("paths=" + spec.path_class.expression);
  // Only when not the box filter, so that every key of a box-filtered reference stays valid.
  if (spec.pixel_sampling != PixelSampling::kArea)
    hasher.addString(std::string("pixel_sampling=") + pixelSamplingName(spec.pixel_sampling));
  // Only for an obscurance, so that every key of a radiance reference stays valid. The fraction
  // is written in full (fmt's shortest round trip), so two that differ in any bit differ here.
  if (spec.obscurance)
    hasher.addString(fmt::format(
        "obscurance={},{},{}", scene::obscuranceFalloffName(spec.obscurance->falloff),
        scene::obscuranceModeName(spec.obscurance->mode), spec.obscurance->d_max_fraction));
  // Only without the environment's occlusion, so that every other key stays valid.
  if (!spec.environment_occlusion) hasher.addString("environment_occlusion=off");
  hasher.addString(kReferenceRendererVersion);
  return hasher.hexDigest();
}

std::string describeReferenceQuantity(const ReferenceSpec& spec) {
  if (spec.obscurance) return scene::describeObscurance(*spec.obscurance);
  return scene::describePathClass(spec.path_class) +
         (spec.environment_occlusion ? "" : ", environment unoccluded");
}

ReferenceStore::ReferenceStore(fs::path root) : root_(std::move(root)) {}

std::mutex& ReferenceStore::renderLock(const std::string& key) {
  std::lock_guard lock(mutex_);
  std::unique_ptr<std::mutex>& render_lock = render_locks_[key];
  if (!render_lock) render_lock = std::make_unique<std::mutex>();
  return *render_lock;
}

StoredReference ReferenceStore::obtain(const scene::Scene& scene, const ReferenceSpec& spec,
                                       bool progress, const WaitingNote& waiting) {
  const RenderSettings settings = renderSettingsOf(spec, progress);
  validateRenderSettings(settings);
  const std::string key = referenceKey(scene, spec);
  const fs::path final_dir = referencesDir(root_) / key;
  std::lock_guard render_lock(renderLock(key));
  if (std::optional<StoredReference> found = loadIntact(final_dir)) return *found;

  // Find an unwritable store before the render, not after it.
  { StagingDir probe(root_, key); }
  // Another process (of this host or another sharing the store) may be rendering the key: wait
  // for its entry rather than render it a second time.
  const fs::path lock_dir = root_ / "locks" / key;
  std::unique_ptr<StoreKeyLock> key_lock;
  bool told = false;
  for (auto pause = std::chrono::milliseconds(100);
       !(key_lock = StoreKeyLock::tryAcquire(lock_dir));
       pause = std::min(pause * 2, std::chrono::milliseconds(2000))) {
    if (std::optional<StoredReference> found = loadIntact(final_dir)) return *found;
    if (waiting && !told) {
      waiting(StoreKeyLock::holderOf(lock_dir));
      told = true;
    }
    std::this_thread::sleep_for(pause);
  }
  // The holder we waited for may have published just before letting go.
  if (std::optional<StoredReference> found = loadIntact(final_dir)) return *found;
  RenderResult result = renderReference(scene, settings);

  // Write the entry's files into a staging directory, then publish it whole.
  StagingDir staging(root_, key);
  StoredReference stored;
  stored.entry = describeEntry(scene, spec, key, result.seconds);
  image::Metadata metadata = referenceMetadata(scene, settings);
  addRunMetadata(metadata, result);
  metadata["gibench/store_key"] = key;
  writeReferenceOutputs(staging.path() / "reference.exr", result, metadata);
  stored.entry.exr_hash = hashFileContents(staging.path() / "reference.exr");
  image::writeTextFile(staging.path() / "entry.json", entryToJson(stored.entry).dump(2) + "\n");
  if (std::optional<StoredReference> theirs = publish(staging, final_dir, root_, key))
    return *theirs;
  stored.entry.dir = final_dir;
  stored.entry.size_bytes = directoryBytes(final_dir);
  stored.entry.current = true;
  stored.mean = std::move(result.mean);
  stored.variance = std::move(result.variance);
  stored.variance_dof = result.variance_dof;
  return stored;
}

bool ReferenceStore::contains(const std::string& key) const {
  std::error_code ec;
  return isHexKey(key) && fs::is_regular_file(referencesDir(root_) / key / "entry.json", ec);
}

std::optional<StoredReference> ReferenceStore::find(const std::string& key) const {
  // Only a key can name an entry: never a path such as "../x".
  if (!isHexKey(key)) return std::nullopt;
  const fs::path dir = referencesDir(root_) / key;
  if (!fs::exists(dir / "entry.json")) return std::nullopt;
  return loadStored(dir);
}

namespace {

// The subdirectories of `<root>/references` (none when it does not exist yet).
std::vector<fs::path> entryDirectories(const fs::path& root) {
  std::vector<fs::path> dirs;
  std::error_code ec;
  const fs::path references = referencesDir(root);
  if (!fs::exists(references, ec)) return dirs;
  for (fs::directory_iterator it(references, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_directory()) dirs.push_back(it->path());
  if (ec)
    throw InputError(fmt::format("cannot read the reference store '{}' ({}); check --store",
                                 references.string(), ec.message()));
  std::sort(dirs.begin(), dirs.end());
  return dirs;
}

bool isHidden(const fs::path& dir) {
  return dir.filename().string().starts_with('.');
}

bool isDebris(const fs::path& dir) {
  if (!dir.filename().string().starts_with(kStagingPrefix)) return false;
  std::error_code ec;
  const auto written = fs::last_write_time(dir, ec);
  return !ec && fs::file_time_type::clock::now() - written > kDebrisAge;
}

}  // namespace

std::vector<StoreEntry> ReferenceStore::list() const {
  std::vector<StoreEntry> entries;
  for (const fs::path& dir : entryDirectories(root_))
    if (!isHidden(dir)) entries.push_back(readStoreEntry(dir));
  std::sort(entries.begin(), entries.end(), [](const StoreEntry& a, const StoreEntry& b) {
    return a.created != b.created ? a.created > b.created : a.key < b.key;
  });
  return entries;
}

GcResult ReferenceStore::collectGarbage(const std::set<std::string>& keep, bool dry_run) const {
  GcResult result;
  for (const fs::path& dir : entryDirectories(root_)) {
    if (isHidden(dir)) {
      if (isDebris(dir)) result.debris.push_back(dir);
      continue;
    }
    try {
      StoreEntry entry = readStoreEntry(dir);
      if (keep.contains(entry.key)) continue;
      result.bytes += entry.size_bytes;
      result.removed.push_back(std::move(entry));
    } catch (const InputError&) {
      result.debris.push_back(dir);  // a damaged entry: of no use to anyone
    }
  }
  for (const fs::path& dir : result.debris) result.bytes += directoryBytes(dir);
  if (dry_run) return result;
  auto remove = [&](const fs::path& dir) {
    std::error_code ec;
    fs::remove_all(dir, ec);
    if (ec)
      throw storeNotWritable(root_, fmt::format("removing {}: {}", dir.string(), ec.message()));
  };
  for (const StoreEntry& entry : result.removed) remove(entry.dir);
  for (const fs::path& dir : result.debris) remove(dir);
  return result;
}

}  // namespace gib::ref
