// OBJ meshes through the scene loader (scene/scene_file.h): the input is "mesh.obj", placed by a
// fixed, valid scene file as both a plain surface and an emitter.
#include "fuzz/fuzz_support.h"
#include "scene/scene_file.h"

#include <string_view>

namespace {

constexpr std::string_view kSceneToml = R"(
[camera]
position = [0.5, 0.5, -3.0]
look_at = [0.5, 0.5, 0.5]
vertical_fov_deg = 40.0

[materials.white]
type = "lambert"
diffuse = [0.7, 0.7, 0.7]

[materials.lamp]
type = "lambert"
diffuse = [0.5, 0.5, 0.5]
emission = [10.0, 10.0, 10.0]

[[meshes]]
file = "mesh.obj"
material = "white"

[[meshes]]
file = "mesh.obj"
material = "lamp"
translate = [0.0, 2.0, 0.0]
)";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gib;
  static const std::filesystem::path scene_path = fuzz::writeInput(
      reinterpret_cast<const std::uint8_t*>(kSceneToml.data()), kSceneToml.size(), "scene.toml");
  fuzz::writeInput(data, size, "mesh.obj");
  fuzz::refusedOnlyAsInputError([&] { scene::loadSceneFile(scene_path); });
  return 0;
}
