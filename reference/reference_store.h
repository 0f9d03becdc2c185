// The reference store: reference renders kept on disk, content-addressed, so a reference is
// rendered once and reused by every later run that needs the same image. The key is the hash of
// the canonical scene (scene::hashScene), the render settings that change the image (size, spp,
// seed, path class) and the reference renderer's version (a hash of its sources made at build
// time), so changing any of them makes a new key rather than a stale hit.
//
// Layout under the root (default gib::defaultStoreRoot(), common/cache_paths.h; `--store DIR`
// chooses another, a network disk say):
//   <root>/references/<key>/reference.exr   mean (RGB) + variance, direct, indirect layers
//   <root>/references/<key>/reference.png   for looking at
//   <root>/references/<key>/entry.json      what was rendered, how, by which version, when
//   <root>/locks/<key>/                     held while a process renders the key
//   <root>/history.sqlite                   the run history (reports/history_db.h), beside it
// An entry is written into a temporary directory and renamed into place: a reader never sees a
// half-written entry, and two processes rendering the same key both end with one whole entry.
#pragma once

#include "image/image.h"
#include "reference/progressive_renderer.h"
#include "scene/path_class.h"
#include "scene/scene.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gib::ref {

// What a reference is of: the scene as the user names it (so `store verify` can load it again)
// and the settings that change the image.
struct ReferenceSpec {
  std::string scene;                          // built-in name or scene file path (loadScene's)
  std::vector<std::string> scene_parameters;  // "key=value" of a built-in scene
  int width = 512;
  int height = 512;
  std::uint32_t spp = 1024;
  std::uint64_t seed = 0;
  scene::PathClass path_class;
  // Where the camera rays go (reference/progressive_renderer.h). A pixel-centre reference has a
  // key of its own; a box-filtered one keeps the key it had before the choice existed.
  PixelSampling pixel_sampling = PixelSampling::kArea;
  // A reference of this obscurance instead of radiance (RenderSettings::obscurance; its path
  // class is then ignored, and left at every path by the harness). A radiance reference keeps
  // the key it had before obscurances existed.
  std::optional<scene::ObscuranceDefinition> obscurance;
  // False: the environment's light reaches diffuse and glossy surfaces unblocked
  // (RenderSettings::environment_occlusion). A reference with occlusion keeps its key.
  bool environment_occlusion = true;
  // The thin lens given over the scene's camera (scene::applyLens) by a suite or the command
  // line, so that the entry can be rendered again (store verification). The key needs no field of
  // its own: the scene's hash includes a lens of radius > 0, and a pinhole keeps its key.
  scene::LensSetting lens;
};

// What a stored reference is of, in results and `store list`: its path class in Heckbert's
// notation, or describeObscurance's words for an obscurance.
std::string describeReferenceQuantity(const ReferenceSpec& spec);

// Everything entry.json records.
struct StoreEntry {
  std::string key;
  std::filesystem::path dir;
  ReferenceSpec spec;
  std::string scene_name;  // scene::Scene::name
  std::string scene_hash;
  std::string renderer_version;  // kReferenceRendererVersion of the build that rendered it
  std::string gibench_version;
  std::string created;  // ISO 8601 UTC
  double render_seconds = 0;
  // Content hash (common/content_hash.h) of reference.exr's bytes, checked on every read, so that
  // a damaged image (a flipped byte, a truncated write on a full disk) is never used as ground
  // truth. Empty in entries of an older gibench, which are therefore never current.
  std::string exr_hash;
  std::uint64_t size_bytes = 0;  // of the entry's files
  // Rendered by this build's renderer and checkable (exr_hash): an entry of another version or
  // of the format without the hash is never a hit, but stays until gc removes it.
  bool current = false;
};

struct StoredReference {
  StoreEntry entry;
  image::Image mean;
  image::Image variance;  // of the per-pixel mean; empty with one replica
  // Degrees of freedom of `variance` (RenderResult::variance_dof).
  std::uint32_t variance_dof = 0;
  bool hit = false;  // found rather than rendered by this call
};

struct GcResult {
  std::vector<StoreEntry> removed;            // or would be, with dry_run
  std::vector<std::filesystem::path> debris;  // temporary directories of interrupted writes
  std::uint64_t bytes = 0;
};

// The store key of `spec` for the loaded scene (lowercase hex).
std::string referenceKey(const scene::Scene& scene, const ReferenceSpec& spec);

class ReferenceStore {
 public:
  // Does not touch the disk; directories are created on the first write.
  explicit ReferenceStore(std::filesystem::path root);

  const std::filesystem::path& root() const { return root_; }

  // Called once with the holder ("host:pid") when another process is rendering the key.
  using WaitingNote = std::function<void(const std::string& holder)>;

  // The entry of `spec`, rendered and stored first when absent. Safe to call from several
  // threads and processes, on one host or many sharing the root: one render per key at a time
  // (reference/reference_store_lock.h); a caller that finds the key being rendered elsewhere
  // waits for that entry, which it then returns as a hit. `progress`: draw a progress bar on a
  // terminal while rendering. Throws gib::InputError when the root cannot be written.
  StoredReference obtain(const scene::Scene& scene, const ReferenceSpec& spec,
                         bool progress = false, const WaitingNote& waiting = {});
  std::optional<StoredReference> find(const std::string& key) const;
  // Whether the store holds an entry of `key` (without reading its images).
  bool contains(const std::string& key) const;

  // Every entry, newest first. An unreadable entry.json throws gib::InputError naming it.
  std::vector<StoreEntry> list() const;

  // Removes the entries whose key is not in `keep`, and the debris of interrupted writes.
  GcResult collectGarbage(const std::set<std::string>& keep, bool dry_run) const;

 private:
  // The lock that lets one thread at a time render `key` in this process.
  std::mutex& renderLock(const std::string& key);

  std::filesystem::path root_;
  std::mutex mutex_;  // guards per-key render locks
  std::map<std::string, std::unique_ptr<std::mutex>> render_locks_;
};

}  // namespace gib::ref
