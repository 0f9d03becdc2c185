// The fixture of the scene-file tests: a folder with two OBJ meshes and a scene file that uses
// every key, and checks that an error is one line positioned in the file.
#pragma once

#include "common/input_error.h"
#include "scene/scene_file.h"
#include "support/temp_dir.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

namespace gib::scene::test {

using ::testing::HasSubstr;

// A unit quad in the z = 0 plane facing +z, as one polygon (two triangles once triangulated).
inline constexpr const char* kQuadObj = R"(# quad
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
f 1 2 3 4
)";

// A unit cube, six quads (twelve triangles), with OBJ materials that the loader must ignore.
inline constexpr const char* kCubeObj = R"(mtllib missing.mtl
o cube
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
usemtl red
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 2 3 7 6
f 3 4 8 7
f 4 1 5 8
)";

inline constexpr const char* kScene = R"(name = "test_room"

[camera]
position = [278.0, 273.0, -800.0]
look_at = [278, 273, 0]
vertical_fov_deg = 39.3077

[image]
width = 320
height = 240

[materials.white]
type = "lambert"
diffuse = [0.7, 0.7, 0.7]

[materials.gloss]
type = "phong"
diffuse = [0.3, 0.3, 0.3]
specular = [0.4, 0.4, 0.4]
exponent = 50.0

[materials.lamp]
type = "lambert"
diffuse = [0.78, 0.78, 0.78]
emission = [17.0, 12.0, 4.0]

[[meshes]]
file = "quad.obj"
material = "lamp"

[[meshes]]
file = "meshes/cube.obj"
material = "gloss"
translate = [10.0, 20.0, 30.0]
scale = [2.0, 3.0, 4.0]

[[lights]]
type = "spot"
position = [0.0, 500.0, 0.0]
direction = [0.0, -2.0, 0.0]
intensity = [100.0, 90.0, 80.0]
cone_angle_deg = 30.0
falloff_exponent = 2.0

[[lights]]
type = "directional"
direction = [0.0, 0.0, -3.0]
irradiance = [1.0, 2.0, 3.0]

[sky]
radiance = [0.1, 0.2, 0.3]
)";

inline void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

// Replaces the one occurrence of `from` in `text`; fails the test if there is none.
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// 1-based line of the first occurrence of `needle`.
inline int lineOf(const std::string& text, const std::string& needle) {
  const std::size_t at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

class SceneFileTest : public ::testing::Test {
 protected:
  SceneFileTest() {
    writeFile(dir_ / "quad.obj", kQuadObj);
    writeFile(dir_ / "meshes" / "cube.obj", kCubeObj);
  }

  std::filesystem::path write(const std::string& text) const {
    writeFile(scenePath(), text);
    return scenePath();
  }
  std::filesystem::path scenePath() const { return dir_ / "scene.toml"; }

  // The message of the InputError that loading `text` throws ("" if none is thrown).
  std::string errorOf(const std::string& text) const {
    try {
      loadSceneFile(write(text));
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no InputError for:\n" << text;
    return "";
  }

  // Expects an InputError naming the file and the line of `needle` in `text`.
  std::string expectErrorAt(const std::string& text, const std::string& needle) const {
    const std::string message = errorOf(text);
    EXPECT_THAT(message,
                HasSubstr(scenePath().string() + ":" + std::to_string(lineOf(text, needle)) + ":"));
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    return message;
  }

  gib::test::TempDir dir_;
};

}  // namespace gib::scene::test
