// The reference store: content-addressed keys, hits and misses, concurrent writers, interrupted
// writes, garbage collection and verification against a fresh render.
#include "reference/reference_store.h"

#include "common/input_error.h"
#include "reference/reference_store_entry.h"
#include "scene/builtin_scenes.h"
#include "support/read_text.h"
#include "support/reference_store_fixtures.h"
#include "support/temp_dir.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

namespace gib::ref {
namespace {

namespace fs = std::filesystem;
using test::obtainReference;
using test::readText;
using test::smallReferenceSpec;
using test::TempDir;
using ::testing::HasSubstr;

bool bitIdentical(const image::Image& a, const image::Image& b) {
  return a.sameSize(b) && std::memcmp(a.data().data(), b.data().data(), a.data().size_bytes()) == 0;
}

// The names in <root>/references.
std::set<std::string> storeDirectories(const fs::path& root) {
  std::set<std::string> names;
  for (const fs::directory_entry& d : fs::directory_iterator(root / "references"))
    names.insert(d.path().filename().string());
  return names;
}

// A directory as an interrupted write leaves it, last written `age` ago.
fs::path makeStagingDebris(const fs::path& root, const std::string& name,
                           std::chrono::minutes age) {
  const fs::path dir = root / "references" / name;
  test::writeFile(dir / "reference.exr", "half an EXR");
  fs::last_write_time(dir, fs::file_time_type::clock::now() - age);
  return dir;
}

TEST(ReferenceStore, MissRendersAndStoresThenHitLoadsTheSamePixels) {
  TempDir dir;
  const ReferenceSpec spec = smallReferenceSpec();
  const StoredReference first = obtainReference(dir.path(), spec);
  EXPECT_FALSE(first.hit);
  const fs::path entry_dir = dir / "references" / first.entry.key;
  EXPECT_EQ(first.entry.dir, entry_dir);
  for (const char* name : {"reference.exr", "reference.png", "entry.json"})
    EXPECT_TRUE(fs::is_regular_file(entry_dir / name)) << name;
  EXPECT_TRUE(first.entry.current);
  EXPECT_GT(first.entry.size_bytes, 0u);
  EXPECT_EQ(first.mean.width(), 24);
  EXPECT_EQ(first.variance.width(), 24);
  const std::string entry_json = readText(entry_dir / "entry.json");

  // A second store on the same root (a later run): found, not rendered.
  const StoredReference second = obtainReference(dir.path(), spec);
  EXPECT_TRUE(second.hit);
  EXPECT_EQ(second.entry.key, first.entry.key);
  EXPECT_EQ(second.entry.created, first.entry.created);
  EXPECT_EQ(readText(entry_dir / "entry.json"), entry_json);
  EXPECT_TRUE(bitIdentical(second.mean, first.mean));
  EXPECT_TRUE(bitIdentical(second.variance, first.variance));
  EXPECT_EQ(storeDirectories(dir.path()), std::set<std::string>{first.entry.key});
}

TEST(ReferenceStore, EntryRecordsWhatWasRenderedAndHow) {
  TempDir dir;
  ReferenceSpec spec = smallReferenceSpec("cornell", 16, 4);
  spec.seed = 9;
  spec.path_class.max_bounces = 1;
  const StoredReference stored = obtainReference(dir.path(), spec);
  const std::optional<StoredReference> found = ReferenceStore(dir.path()).find(stored.entry.key);
  ASSERT_TRUE(found);
  const StoreEntry& e = found->entry;
  EXPECT_EQ(e.spec.scene, "cornell");
  EXPECT_EQ(e.spec.width, 16);
  EXPECT_EQ(e.spec.spp, 4u);
  EXPECT_EQ(e.spec.seed, 9u);
  EXPECT_EQ(e.spec.path_class, spec.path_class);
  EXPECT_EQ(e.scene_name, "cornell");
  EXPECT_EQ(e.scene_hash, scene::hashScene(scene::loadScene("cornell")));
  EXPECT_EQ(e.renderer_version.size(), 16u);
  EXPECT_EQ(e.created.size(), std::string("2026-11-22T07:55:31.123Z").size());
  EXPECT_GT(e.render_seconds, 0);
}

// A lens given over the scene's camera is recorded in entry.json (for verification to render it
// again) and keyed through the scene's hash; an entry without one reads back as the scene's own.
TEST(ReferenceStore, EntryRecordsTheLensGivenOverTheScene) {
  TempDir dir;
  ReferenceSpec spec = smallReferenceSpec("cornell", 8, 2);
  spec.lens.radius = 20.0;
  spec.lens.focus_distance = 1000.0;
  const StoredReference stored = obtainReference(dir.path(), spec);
  const std::optional<StoredReference> found = ReferenceStore(dir.path()).find(stored.entry.key);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->entry.spec.lens, spec.lens);
  scene::Scene lens = scene::loadScene("cornell");
  lens.camera.lens_radius = 20.0f;
  lens.camera.focus_distance = 1000.0f;
  EXPECT_EQ(found->entry.scene_hash, scene::hashScene(lens));
  EXPECT_NE(found->entry.key,
            obtainReference(dir.path(), smallReferenceSpec("cornell", 8, 2)).entry.key);
  const std::optional<StoredReference> pinhole =
      ReferenceStore(dir.path())
          .find(referenceKey(scene::loadScene("cornell"), smallReferenceSpec("cornell", 8, 2)));
  ASSERT_TRUE(pinhole);
  EXPECT_EQ(pinhole->entry.spec.lens, scene::LensSetting{});
}

TEST(ReferenceStore, KeyChangesWithEverySettingAndIsStable) {
  const scene::Scene cornell = scene::loadScene("cornell");
  const ReferenceSpec base = smallReferenceSpec();
  const std::string key = referenceKey(cornell, base);
  EXPECT_EQ(key.size(), 32u);
  EXPECT_EQ(referenceKey(scene::loadScene("cornell"), base), key);

  std::set<std::string> keys = {key};
  auto addVariant = [&](const scene::Scene& scene, auto change) {
    ReferenceSpec spec = base;
    change(spec);
    keys.insert(referenceKey(scene, spec));
  };
  addVariant(cornell, [](ReferenceSpec& s) { s.width = 25; });
  addVariant(cornell, [](ReferenceSpec& s) { s.height = 25; });
  addVariant(cornell, [](ReferenceSpec& s) { s.spp = 65; });
  addVariant(cornell, [](ReferenceSpec& s) { s.seed = 1; });
  addVariant(cornell, [](ReferenceSpec& s) { s.path_class.min_bounces = 1; });
  addVariant(cornell, [](ReferenceSpec& s) { s.path_class.max_bounces = 1; });
  addVariant(scene::loadScene("furnace"), [](ReferenceSpec&) {});
  addVariant(scene::loadScene("cloud"), [](ReferenceSpec&) {});
  addVariant(scene::loadScene("cloud", {"albedo=0.8"}), [](ReferenceSpec&) {});
  EXPECT_EQ(keys.size(), 10u);

  // Width and height are not interchangeable.
  ReferenceSpec wide = base, tall = base;
  wide.width = 32;
  tall.height = 32;
  EXPECT_NE(referenceKey(cornell, wide), referenceKey(cornell, tall));
}

TEST(ReferenceStore, TwoThreadsObtainingOneKeyRenderOnce) {
  TempDir dir;
  ReferenceStore store(dir.path());
  const scene::Scene cornell = scene::loadScene("cornell");
  const ReferenceSpec spec = smallReferenceSpec();
  StoredReference a, b;
  std::thread first([&] { a = store.obtain(cornell, spec); });
  std::thread second([&] { b = store.obtain(cornell, spec); });
  first.join();
  second.join();
  EXPECT_NE(a.hit, b.hit) << "exactly one of the two renders";
  EXPECT_EQ(a.entry.created, b.entry.created);
  EXPECT_TRUE(bitIdentical(a.mean, b.mean));
  EXPECT_EQ(storeDirectories(dir.path()), std::set<std::string>{a.entry.key});
}

TEST(ReferenceStore, TwoStoresOnOneRootRenderOnceAndEndWithOneWholeEntry) {
  // Two stores on one root behave like two processes (or two hosts on a shared disk): no lock in
  // memory is shared, only the store's lock directory; one renders, the other waits for its entry.
  TempDir dir;
  const ReferenceSpec spec = smallReferenceSpec();
  StoredReference a, b;
  std::thread first([&] { a = obtainReference(dir.path(), spec); });
  std::thread second([&] { b = obtainReference(dir.path(), spec); });
  first.join();
  second.join();
  EXPECT_NE(a.hit, b.hit) << "exactly one of the two renders";
  EXPECT_EQ(a.entry.created, b.entry.created);
  EXPECT_TRUE(bitIdentical(a.mean, b.mean));
  EXPECT_TRUE(fs::is_empty(dir / "locks")) << "the lock is released";
  EXPECT_EQ(storeDirectories(dir.path()), std::set<std::string>{a.entry.key});
  EXPECT_EQ(ReferenceStore(dir.path()).list().size(), 1u);
}

TEST(ReferenceStore, ListsNewestFirstAndMarksEntriesOfAnotherRenderer) {
  TempDir dir;
  const StoredReference older = obtainReference(dir.path(), smallReferenceSpec("cornell", 16, 4));
  const StoredReference newer = obtainReference(dir.path(), smallReferenceSpec("furnace", 16, 4));
  test::setStoredRendererVersion(older.entry, "0123456789abcdef");
  const std::vector<StoreEntry> entries = ReferenceStore(dir.path()).list();
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].key, newer.entry.key);
  EXPECT_TRUE(entries[0].current);
  EXPECT_EQ(entries[1].key, older.entry.key);
  EXPECT_FALSE(entries[1].current);
  EXPECT_EQ(entries[1].renderer_version, "0123456789abcdef");
}

TEST(ReferenceStore, InterruptedWriteIsIgnoredAndCollected) {
  TempDir dir;
  const StoredReference stored = obtainReference(dir.path(), smallReferenceSpec("cornell", 16, 4));
  const fs::path old_debris = makeStagingDebris(dir.path(), ".tmp-" + stored.entry.key + "-4242-0",
                                                std::chrono::minutes(120));
  // A younger one may belong to a process writing right now: gc leaves it.
  const fs::path young = makeStagingDebris(dir.path(), ".tmp-" + stored.entry.key + "-4243-0",
                                           std::chrono::minutes(1));
  ReferenceStore store(dir.path());
  EXPECT_EQ(store.list().size(), 1u);
  EXPECT_TRUE(store.find(stored.entry.key));
  EXPECT_FALSE(store.find(".tmp-" + stored.entry.key + "-4242-0"));

  const GcResult gc = store.collectGarbage({stored.entry.key}, /*dry_run=*/false);
  EXPECT_TRUE(gc.removed.empty());
  EXPECT_EQ(gc.debris, std::vector<fs::path>{old_debris});
  EXPECT_EQ(gc.bytes, std::string("half an EXR").size());
  EXPECT_FALSE(fs::exists(old_debris));
  EXPECT_TRUE(fs::exists(young));
  EXPECT_TRUE(store.find(stored.entry.key));
}

TEST(ReferenceStore, GarbageCollectionKeepsTheKeepSet) {
  TempDir dir;
  const StoredReference kept = obtainReference(dir.path(), smallReferenceSpec("cornell", 16, 4));
  const StoredReference unused = obtainReference(dir.path(), smallReferenceSpec("furnace", 16, 4));
  ReferenceStore store(dir.path());

  const GcResult dry = store.collectGarbage({kept.entry.key}, /*dry_run=*/true);
  ASSERT_EQ(dry.removed.size(), 1u);
  EXPECT_EQ(dry.removed[0].key, unused.entry.key);
  EXPECT_EQ(dry.bytes, unused.entry.size_bytes);
  EXPECT_EQ(store.list().size(), 2u) << "a dry run removes nothing";

  const GcResult gc = store.collectGarbage({kept.entry.key}, /*dry_run=*/false);
  EXPECT_EQ(gc.bytes, dry.bytes);
  EXPECT_FALSE(store.find(unused.entry.key));
  EXPECT_TRUE(store.find(kept.entry.key));
  EXPECT_EQ(storeDirectories(dir.path()), std::set<std::string>{kept.entry.key});
}

TEST(ReferenceStore, DamagedEntryIsNamedByListReplacedByObtainAndCollected) {
  TempDir dir;
  const ReferenceSpec spec = smallReferenceSpec("cornell", 16, 4);
  const StoredReference stored = obtainReference(dir.path(), spec);
  test::writeFile(stored.entry.dir / "entry.json", "{ not json");
  ReferenceStore store(dir.path());
  try {
    store.list();
    ADD_FAILURE() << "list() accepted a damaged entry.json";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr(stored.entry.key + "/entry.json"));
  }
  EXPECT_EQ(store.collectGarbage({}, /*dry_run=*/true).debris,
            std::vector<fs::path>{stored.entry.dir});

  const StoredReference again = store.obtain(scene::loadScene("cornell"), spec);
  EXPECT_FALSE(again.hit);
  EXPECT_TRUE(bitIdentical(again.mean, stored.mean));
  EXPECT_EQ(store.list().size(), 1u);
  EXPECT_EQ(storeDirectories(dir.path()), std::set<std::string>{stored.entry.key});
}

// Damage a shared disk or a full disk can do to a stored image: whatever byte changes, or wherever
// the file is cut, the entry is refused with one line, and obtaining it renders it again to the
// same pixels. It is never returned as ground truth.
TEST(ReferenceStore, ADamagedImageIsNeverUsedAsGroundTruth) {
  TempDir dir;
  const ReferenceSpec spec = smallReferenceSpec("cornell", 16, 4);
  const StoredReference stored = obtainReference(dir.path(), spec);
  const fs::path exr = stored.entry.dir / "reference.exr";
  const std::string original = readText(exr);
  ReferenceStore store(dir.path());
  const auto refusedWith = [&](const std::string& damaged, const std::string& expected) {
    test::writeFile(exr, damaged);
    try {
      store.find(stored.entry.key);
      return ::testing::AssertionFailure() << "a damaged image was read as the reference";
    } catch (const InputError& e) {
      if (std::string(e.what()).find(expected) == std::string::npos)
        return ::testing::AssertionFailure() << "unexpected message: " << e.what();
    }
    return ::testing::AssertionSuccess();
  };
  // Every 1/97 of the file, header and pixel data alike, one byte at a time.
  int flips = 0;
  for (std::size_t at = 0; at < original.size(); at += original.size() / 97 + 1, ++flips) {
    std::string damaged = original;
    damaged[at] = char(damaged[at] ^ 0x20);
    EXPECT_TRUE(refusedWith(damaged, "does not match the content hash")) << "byte " << at;
  }
  EXPECT_GE(flips, 97);
  for (std::size_t length :
       {std::size_t(0), std::size_t(8), original.size() / 2, original.size() - 1})
    EXPECT_TRUE(refusedWith(original.substr(0, length), "does not match the content hash"))
        << "cut at " << length;

  // Left damaged, it is rendered again: the same pixels, and a whole entry afterwards.
  const StoredReference again = store.obtain(scene::loadScene("cornell"), spec);
  EXPECT_FALSE(again.hit);
  EXPECT_TRUE(bitIdentical(again.mean, stored.mean));
  EXPECT_TRUE(bitIdentical(store.find(stored.entry.key)->mean, stored.mean));
}

TEST(ReferenceStore, AnEntryWithoutItsContentHashIsRenderedAgain) {
  TempDir dir;
  const ReferenceSpec spec = smallReferenceSpec("cornell", 16, 4);
  const StoredReference stored = obtainReference(dir.path(), spec);
  ReferenceStore store(dir.path());
  // The format before the hash existed: listed, not current, never a hit.
  test::setStoredEntryField(stored.entry, "format", kStoreEntryFormatWithoutHash);
  ASSERT_EQ(store.list().size(), 1u);
  EXPECT_FALSE(store.list().front().current);
  EXPECT_THAT([&] { store.find(stored.entry.key); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("without a content hash")));
  StoredReference again = store.obtain(scene::loadScene("cornell"), spec);
  EXPECT_FALSE(again.hit);
  EXPECT_TRUE(store.list().front().current);
  // A current-format entry that lost the field is damaged, and likewise replaced.
  test::setStoredEntryField(again.entry, "reference_exr_hash", "");
  EXPECT_THROW(store.find(stored.entry.key), InputError);
  EXPECT_FALSE(store.obtain(scene::loadScene("cornell"), spec).hit);
  EXPECT_TRUE(bitIdentical(store.find(stored.entry.key)->mean, stored.mean));
}

TEST(ReferenceStore, UnwritableRootIsAnInputErrorBeforeRendering) {
  TempDir dir;
  test::writeFile(dir / "a_file", "not a directory");
  ReferenceStore store(dir / "a_file" / "store");
  const auto start = std::chrono::steady_clock::now();
  try {
    // 512×512 at 1024 spp would take minutes: the error must come first.
    store.obtain(scene::loadScene("cornell"), smallReferenceSpec("cornell", 512, 1024));
    ADD_FAILURE() << "obtain() wrote into a path under a file";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("cannot write the reference store"));
    EXPECT_THAT(e.what(), HasSubstr("--store"));
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

TEST(ReferenceStore, FindTakesOnlyKeys) {
  TempDir dir;
  ReferenceStore store(dir.path());
  EXPECT_FALSE(store.find("0123456789abcdef0123456789abcdef"));
  EXPECT_FALSE(store.find("../x"));
  EXPECT_FALSE(store.find(""));
  EXPECT_TRUE(store.list().empty()) << "a store that was never written is empty";
}

}  // namespace
}  // namespace gib::ref
