#include "support/reference_store_fixtures.h"

#include "common/content_hash.h"
#include "image/exr_io.h"
#include "scene/builtin_scenes.h"

#include <nlohmann/json.hpp>

#include <fstream>

namespace gib::test {

ref::ReferenceSpec smallReferenceSpec(const std::string& scene, int size, std::uint32_t spp) {
  ref::ReferenceSpec spec;
  spec.scene = scene;
  spec.width = spec.height = size;
  spec.spp = spp;
  return spec;
}

ref::StoredReference obtainReference(const std::filesystem::path& root,
                                     const ref::ReferenceSpec& spec) {
  ref::ReferenceStore store(root);
  // The scene the spec describes: its lens over the scene's camera, as store verification has it.
  scene::Scene scene = scene::loadScene(spec.scene, spec.scene_parameters);
  scene::applyLens(scene.camera, spec.lens, "lens.radius", "lens.focus_distance");
  return store.obtain(scene, spec);
}

void scaleStoredMean(const ref::StoreEntry& entry, float factor) {
  const std::filesystem::path exr = entry.dir / "reference.exr";
  image::ExrFile file = image::readExr(exr);
  for (image::Layer& layer : file.layers)
    if (layer.name.empty())
      for (float& v : layer.image.data()) v *= factor;
  image::writeExr(exr, file.layers, file.metadata);
  setStoredEntryField(entry, "reference_exr_hash", hashFileContents(exr));
}

void setStoredRendererVersion(const ref::StoreEntry& entry, const std::string& version) {
  setStoredEntryField(entry, "renderer_version", version);
}

void setStoredEntryField(const ref::StoreEntry& entry, const std::string& field,
                         const std::string& value) {
  const std::filesystem::path path = entry.dir / "entry.json";
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(std::ifstream(path));
  j[field] = value;
  writeFile(path, j.dump(2));
}

void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

}  // namespace gib::test
