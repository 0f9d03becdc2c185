// The [materials.*] tables of a scene file (format: scene_file.h): Lambert, Phong, mirror and
// glass materials, each checked with a positioned error.
#pragma once

#include "scene/scene_file_reader.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace gib::scene {

// Reads [materials.*] in the order of the file; `indices` maps names to their positions.
std::vector<Material> readSceneFileMaterials(const SceneTableReader& root,
                                             std::map<std::string, std::uint32_t>& indices);

}  // namespace gib::scene
