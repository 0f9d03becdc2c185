// What the parts of the scene-file reader (scene_file.cpp, scene_file_materials.cpp,
// obj_mesh.cpp) share: a TOML table reader with the vectors and colours of scene files. Internal
// to the scene layer; the format is documented in scene_file.h.
#pragma once

#include "common/toml_reader.h"
#include "scene/scene.h"

#include <fmt/format.h>
#include <glm/vec3.hpp>

#include <cmath>
#include <string_view>

namespace gib::scene {

inline bool isFiniteVec3(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The shared reader (common/toml_reader.h) plus the vectors and colours of scene files.
class SceneTableReader : public TomlTableReader {
 public:
  using TomlTableReader::TomlTableReader;

  glm::vec3 vec3(const toml::node& node, std::string_view key) const {
    const toml::array* array = node.as_array();
    glm::vec3 v(NAN);
    if (array && array->size() == 3) {
      for (int i = 0; i < 3; ++i)
        v[i] = static_cast<float>(tomlNumber(*array->get(static_cast<std::size_t>(i))));
    }
    if (!isFiniteVec3(v))
      errors().fail(node, fmt::format("{} must be an array of 3 numbers", path(key)),
                    "write it as [x, y, z] with finite values");
    return v;
  }

  // An RGB quantity: reflectance, radiance, intensity or irradiance, never negative.
  Rgb rgb(const toml::node& node, std::string_view key) const {
    const glm::vec3 v = vec3(node, key);
    if (v.r < 0 || v.g < 0 || v.b < 0)
      errors().fail(
          node, fmt::format("{} must not be negative, got [{}, {}, {}]", path(key), v.r, v.g, v.b),
          "use values >= 0");
    return v;
  }

  template <typename Read, typename T>
  T optional(std::string_view key, Read read, T fallback) const {
    const toml::node* node = find(key);
    return node ? (this->*read)(*node, key) : fallback;
  }
};

}  // namespace gib::scene
