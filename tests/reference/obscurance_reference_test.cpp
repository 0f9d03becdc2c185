// A reference of an obscurance instead of radiance (RenderSettings::obscurance, ReferenceSpec::
// obscurance): deterministic and with its variance layer like any reference, W = 1 exactly over an
// open floor, its metadata, and the store's keys and entries (radiance keys unchanged).
#include "common/input_error.h"
#include "reference/progressive_renderer.h"
#include "reference/reference_output.h"
#include "reference/reference_store.h"
#include "reference/reference_store_entry.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"
#include "support/reference_store_fixtures.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <set>

namespace gib::ref {
namespace {

namespace fs = std::filesystem;
using scene::ObscuranceDefinition;
using scene::ObscuranceFalloff;
using scene::ObscuranceMode;

bool bitIdentical(const image::Image& a, const image::Image& b) {
  return a.sameSize(b) && std::memcmp(a.data().data(), b.data().data(), a.data().size_bytes()) == 0;
}

RenderSettings obscuranceSettings(ObscuranceDefinition definition = {}) {
  RenderSettings settings;
  settings.width = 40;
  settings.height = 24;  // not a multiple of the tile size
  settings.spp = 8;
  settings.obscurance = definition;
  return settings;
}

TEST(ObscuranceReference, ImagesAreBitIdenticalAcrossThreadCountsWithAVarianceLayer) {
  const scene::Scene cornell = scene::loadScene("cornell");
  RenderSettings settings =
      obscuranceSettings({ObscuranceFalloff::kSqrt, ObscuranceMode::kSpectral, 0.25f});
  settings.threads = 1;
  const RenderResult one = renderReference(cornell, settings);
  settings.threads = 2;
  const RenderResult two = renderReference(cornell, settings);
  EXPECT_TRUE(bitIdentical(one.mean, two.mean));
  EXPECT_TRUE(bitIdentical(one.variance, two.variance));
  EXPECT_EQ(one.rays, two.rays);
  EXPECT_EQ(one.replicas, 4u);
  EXPECT_EQ(one.variance_dof, 3u);
  ASSERT_TRUE(one.variance.sameSize(one.mean));
  // The mean is all `direct`; nothing is `indirect`.
  EXPECT_TRUE(bitIdentical(one.direct, one.mean));
  EXPECT_TRUE(std::all_of(one.indirect.data().begin(), one.indirect.data().end(),
                          [](float v) { return v == 0.0f; }));
  // Values of an obscurance (spectral: bounded by the largest albedo), not of radiance, and
  // noisy somewhere.
  EXPECT_TRUE(std::all_of(one.mean.data().begin(), one.mean.data().end(),
                          [](float v) { return v >= 0.0f && v <= 1.0f; }));
  EXPECT_TRUE(std::any_of(one.variance.data().begin(), one.variance.data().end(),
                          [](float v) { return v > 0.0f; }));
  // Unlike the radiance of the same settings.
  settings.obscurance.reset();
  EXPECT_FALSE(bitIdentical(renderReference(cornell, settings).mean, one.mean));
}

TEST(ObscuranceReference, OpenFloorSeenFromAboveIsOneEverywhere) {
  scene::Scene s;
  s.name = "floor";
  scene::Material floor;
  floor.name = "floor";
  floor.diffuse = scene::Rgb(0.5f);
  s.materials = {floor};
  scene::Mesh mesh;
  scene::appendQuad(mesh, {-20, 0, -20}, {-20, 0, 20}, {20, 0, 20}, {20, 0, -20});
  s.meshes = {mesh};
  s.camera.position = {0, 5, 0};
  s.camera.look_at = {0, 0, 0};
  s.camera.up = {0, 0, 1};
  for (PixelSampling sampling : {PixelSampling::kArea, PixelSampling::kCenter}) {
    RenderSettings settings = obscuranceSettings();
    settings.pixel_sampling = sampling;
    std::vector<std::uint32_t> checkpoints;
    const RenderResult r = renderReference(
        s, settings, [&](std::uint32_t spp, const image::Image&) { checkpoints.push_back(spp); });
    EXPECT_TRUE(
        std::all_of(r.mean.data().begin(), r.mean.data().end(), [](float v) { return v == 1.0f; }));
    EXPECT_TRUE(std::all_of(r.variance.data().begin(), r.variance.data().end(),
                            [](float v) { return v == 0.0f; }));
    EXPECT_EQ(checkpoints, (std::vector<std::uint32_t>{1, 2, 4, 8}));
  }
}

TEST(ObscuranceReference, TracesNoLightPathsAndSaysWhatItIs) {
  const scene::Scene glass = scene::loadScene("cornell", {"spheres=glass"});
  RenderSettings settings =
      obscuranceSettings({ObscuranceFalloff::kAmbientOcclusion, ObscuranceMode::kScalar, 0.1f});
  settings.spp = 2;
  EXPECT_FALSE(renderReference(glass, settings).light_paths);
  const image::Metadata m = referenceMetadata(glass, settings);
  EXPECT_EQ(m.at("gibench/obscurance"), "obscurance(ambient_occlusion, scalar, d_max=0.1)");
  EXPECT_EQ(m.at("gibench/light_paths"), "none");
  EXPECT_NE(m.at("gibench/parameters").find("\"obscurance\""), std::string::npos);
  EXPECT_EQ(referenceMetadata(glass, obscuranceSettings()).count("gibench/obscurance"), 1u);
  settings.obscurance.reset();
  EXPECT_EQ(referenceMetadata(glass, settings).count("gibench/obscurance"), 0u);
  // A bad d_max is refused before anything renders.
  settings.obscurance = ObscuranceDefinition{};
  settings.obscurance->d_max_fraction = 0;
  EXPECT_THROW(renderReference(glass, settings), InputError);
}

TEST(ObscuranceReference, StoreKeysOfObscurancesAreTheirOwn) {
  const scene::Scene cornell = scene::loadScene("cornell");
  ReferenceSpec spec = test::smallReferenceSpec();
  const std::string radiance = referenceKey(cornell, spec);
  std::set<std::string> keys = {radiance};
  for (const ObscuranceDefinition& d :
       {ObscuranceDefinition{},
        ObscuranceDefinition{ObscuranceFalloff::kAmbientOcclusion, ObscuranceMode::kScalar, 0.25f},
        ObscuranceDefinition{ObscuranceFalloff::kSqrt, ObscuranceMode::kSpectral, 0.25f},
        ObscuranceDefinition{ObscuranceFalloff::kSqrt, ObscuranceMode::kScalar, 0.2500001f}}) {
    spec.obscurance = d;
    keys.insert(referenceKey(cornell, spec));
  }
  EXPECT_EQ(keys.size(), 5u);
  spec.obscurance.reset();
  EXPECT_EQ(referenceKey(cornell, spec), radiance);
}

TEST(ObscuranceReference, EntryRecordsTheObscuranceAndOnlyThen) {
  test::TempDir dir;
  StoreEntry entry;
  entry.spec = test::smallReferenceSpec();
  entry.spec.obscurance =
      ObscuranceDefinition{ObscuranceFalloff::kAmbientOcclusion, ObscuranceMode::kSpectral, 0.1f};
  entry.key = "0123456789abcdef0123456789abcdef";
  entry.scene_name = "cornell";
  entry.exr_hash = "hash";
  const nlohmann::ordered_json json = entryToJson(entry);
  EXPECT_EQ(json.at("spec").at("obscurance").at("falloff"), "ambient_occlusion");
  fs::create_directories(dir / entry.key);
  std::ofstream(dir / entry.key / "entry.json") << json.dump(2);
  const StoreEntry read = readStoreEntry(dir / entry.key);
  EXPECT_EQ(read.spec.obscurance, entry.spec.obscurance);
  EXPECT_EQ(renderSettingsOf(read.spec, false).obscurance, entry.spec.obscurance);
  EXPECT_EQ(describeReferenceQuantity(read.spec),
            "obscurance(ambient_occlusion, spectral, d_max=0.1)");

  entry.spec.obscurance.reset();
  EXPECT_FALSE(entryToJson(entry).at("spec").contains("obscurance"));
  EXPECT_EQ(describeReferenceQuantity(entry.spec), "L(D|S|P)*E");
}

TEST(ObscuranceReference, StoreRendersTheObscuranceAndFindsItAgain) {
  test::TempDir dir;
  ReferenceSpec spec = test::smallReferenceSpec("cornell", 16, 8);
  spec.pixel_sampling = PixelSampling::kCenter;
  spec.obscurance = ObscuranceDefinition{};
  const StoredReference first = test::obtainReference(dir.path(), spec);
  EXPECT_FALSE(first.hit);
  const StoredReference again = test::obtainReference(dir.path(), spec);
  EXPECT_TRUE(again.hit);
  EXPECT_TRUE(bitIdentical(first.mean, again.mean));
  EXPECT_EQ(again.entry.spec.obscurance, spec.obscurance);
  const RenderResult direct =
      renderReference(scene::loadScene("cornell"), renderSettingsOf(spec, false));
  EXPECT_TRUE(bitIdentical(direct.mean, first.mean));
  EXPECT_EQ(again.variance_dof, 3u);
}

}  // namespace
}  // namespace gib::ref
