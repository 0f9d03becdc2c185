// The furnace: the camera inside a closed sphere whose walls have albedo 0.5 and emit 0.5. The
// radiance L seen anywhere satisfies L = Le + ρ·L, so L = 0.5 / (1 − 0.5) = 1 exactly, for every
// pixel and every sampling strategy: a known answer for the reference renderer.
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"

namespace gib::scene {

Scene makeFurnace(const ParameterValues&) {
  Scene scene;
  scene.name = "furnace";
  scene.provenance = "analytic test scene: L = Le / (1 - albedo) = 1";
  Material wall;
  wall.name = "furnace_wall";
  wall.diffuse = Rgb(0.5f);
  wall.emission = Rgb(0.5f);
  scene.materials.push_back(wall);

  Mesh sphere;
  sphere.name = "sphere";
  sphere.material = 0;
  // The tessellation does not matter for the answer: any closed surface works. Emission is
  // one-sided, so the triangles face inwards, towards the camera.
  appendSphere(sphere, glm::vec3(0.0f), 1.0f, 16, 32, /*inward=*/true);
  scene.meshes.push_back(std::move(sphere));

  scene.camera.position = {0.0f, 0.0f, 0.0f};
  scene.camera.look_at = {0.0f, 0.0f, -1.0f};
  scene.camera.up = {0.0f, 1.0f, 0.0f};
  scene.camera.vertical_fov_deg = 90.0f;
  scene.default_width = 64;
  scene.default_height = 64;
  return scene;
}

}  // namespace gib::scene
