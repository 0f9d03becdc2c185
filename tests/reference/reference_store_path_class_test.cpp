// The reference store and path classes: a class of bounces keeps the key and entry it had before
// path expressions existed (stores already filled stay valid); an expression class has keys of its
// own and is read back from its entry.
#include "common/content_hash.h"
#include "gib/reference_renderer_version.h"
#include "reference/reference_store.h"
#include "reference/reference_store_entry.h"
#include "scene/builtin_scenes.h"
#include "scene/path_expression.h"
#include "support/reference_store_fixtures.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>

namespace gib::ref {
namespace {

namespace fs = std::filesystem;

// The key as the store computed it before path expressions (format "gibench-reference-key/1",
// box filter), written out here so that a change to referenceKey cannot move it unnoticed.
std::string keyBeforePathExpressions(const scene::Scene& scene, const ReferenceSpec& spec) {
  ContentHasher hasher;
  hasher.addString("gibench-reference-key/1");
  hasher.addString(scene::hashScene(scene));
  hasher.addU64(static_cast<std::uint64_t>(spec.width));
  hasher.addU64(static_cast<std::uint64_t>(spec.height));
  hasher.addU64(spec.spp);
  hasher.addU64(spec.seed);
  hasher.addU64(static_cast<std::uint64_t>(spec.path_class.min_bounces));
  hasher.addU64(static_cast<std::uint64_t>(spec.path_class.max_bounces));
  hasher.addString(kReferenceRendererVersion);
  return hasher.hexDigest();
}

ReferenceSpec withClass(scene::PathClass path_class) {
  ReferenceSpec spec = test::smallReferenceSpec();
  spec.path_class = std::move(path_class);
  return spec;
}

TEST(ReferenceStorePathClass, KeysOfBounceClassesAreThoseOfBefore) {
  const scene::Scene cornell = scene::loadScene("cornell");
  for (const scene::PathClass& c :
       {scene::PathClass{}, scene::PathClass{0, 1}, scene::PathClass{2, 5},
        scene::PathClass{3, scene::PathClass::kUnlimited}}) {
    SCOPED_TRACE(scene::describePathClass(c));
    const ReferenceSpec spec = withClass(c);
    EXPECT_EQ(referenceKey(cornell, spec), keyBeforePathExpressions(cornell, spec));
  }
}

TEST(ReferenceStorePathClass, ExpressionClassesHaveKeysOfTheirOwn) {
  const scene::Scene cornell = scene::loadScene("cornell");
  std::set<std::string> keys = {referenceKey(cornell, withClass({})),
                                referenceKey(cornell, withClass({0, 1}))};
  // Even an expression that means every path is keyed apart from the bounce class: the key
  // follows what was asked for, not what it means.
  for (const char* text : {"LS+DE", "LDSE", "L(D|S|P)*E"})
    keys.insert(referenceKey(cornell, withClass(scene::PathClass::ofExpression(
                                          scene::PathExpression::parse(text).text()))));
  EXPECT_EQ(keys.size(), 5u);
}

TEST(ReferenceStorePathClass, EntryRecordsAnExpressionAndOnlyThen) {
  test::TempDir dir;
  StoreEntry entry;
  entry.spec = withClass(scene::PathClass::ofExpression("LS+DE"));
  entry.key = "0123456789abcdef0123456789abcdef";
  entry.scene_name = "cornell";
  entry.exr_hash = "hash";
  const nlohmann::ordered_json json = entryToJson(entry);
  EXPECT_EQ(json.at("spec").at("paths"), "LS+DE");
  fs::create_directories(dir / entry.key);
  std::ofstream(dir / entry.key / "entry.json") << json.dump(2);
  EXPECT_EQ(readStoreEntry(dir / entry.key).spec.path_class, entry.spec.path_class);

  // A class of bounces writes the entry it wrote before, without the key.
  entry.spec = withClass({0, 1});
  EXPECT_FALSE(entryToJson(entry).at("spec").contains("paths"));
}

// A reference without the environment's occlusion (RenderSettings::environment_occlusion) is
// keyed apart and says so, in its entry and its description; one with it keeps its key and entry.
TEST(ReferenceStorePathClass, EnvironmentWithoutOcclusionHasAKeyOfItsOwn) {
  const scene::Scene outdoor = scene::loadScene("outdoor", {"sky_resolution=32"});
  ReferenceSpec spec = withClass({1, 1});
  const std::string with = referenceKey(outdoor, spec);
  EXPECT_EQ(with, keyBeforePathExpressions(outdoor, spec));
  spec.environment_occlusion = false;
  EXPECT_NE(referenceKey(outdoor, spec), with);
  EXPECT_EQ(describeReferenceQuantity(spec),
            scene::describePathClass(spec.path_class) + ", environment unoccluded");

  test::TempDir dir;
  StoreEntry entry;
  entry.spec = spec;
  entry.key = "0123456789abcdef0123456789abcdef";
  entry.scene_name = "outdoor";
  entry.exr_hash = "hash";
  EXPECT_EQ(entryToJson(entry).at("spec").at("environment_occlusion"), false);
  fs::create_directories(dir / entry.key);
  std::ofstream(dir / entry.key / "entry.json") << entryToJson(entry).dump(2);
  EXPECT_FALSE(readStoreEntry(dir / entry.key).spec.environment_occlusion);
  EXPECT_FALSE(renderSettingsOf(readStoreEntry(dir / entry.key).spec, false).environment_occlusion);
  entry.spec.environment_occlusion = true;
  EXPECT_FALSE(entryToJson(entry).at("spec").contains("environment_occlusion"));
}

}  // namespace
}  // namespace gib::ref
