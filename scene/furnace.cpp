// The furnace: the camera inside a closed sphere whose walls have albedo 0.5 and emit 0.5. The
// radiance L seen anywhere satisfies L = Le + ρ·L, so L = 0.5 / (1 − 0.5) = 1 exactly, for every
// pixel and every sampling strategy: a known answer for the reference renderer. An object that
// neither absorbs nor emits (a perfect mirror, a lossless glass sphere) leaves the answer at 1:
// every direction it sends a path to sees radiance 1 (the glass's radiance scaling by η² inside is
// undone on the way out), so every pixel stays 1.0 with it in view.
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"
#include "scene/metals.h"

#include <string>
#include <utility>

namespace gib::scene {

namespace {

// In front of the camera, filling about a third of the 90° view, smooth-shaded so that its
// reflection and refraction look like a sphere's.
constexpr glm::vec3 kObjectCentre{0.0f, 0.0f, -0.5f};
constexpr float kObjectRadius = 0.25f;
constexpr int kObjectRings = 64;
constexpr int kObjectSegments = 128;

// The object that `object` asks for: its material and a sphere of it.
void addObject(Scene& scene, const std::string& object) {
  Material material;
  if (object == "mirror") {
    material = mirrorMaterial("mirror", *findMetal("perfect"));
  } else {
    material.name = "glass";
    material.type = MaterialType::kGlass;
    material.ior = 1.5f;
  }
  appendSphere(addMeshOfMaterial(scene, object + "_sphere", std::move(material)), kObjectCentre,
               kObjectRadius, kObjectRings, kObjectSegments, /*inward=*/false,
               SphereShading::kSmooth);
}

}  // namespace

ParameterTable furnaceParameters() {
  return {
      choiceParameter("object", "none", {"none", "mirror", "glass"},
                      "a sphere in front of the camera: a perfect mirror or lossless glass (ior "
                      "1.5); every pixel stays 1.0"),
  };
}

Scene makeFurnace(const ParameterValues& parameters) {
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
  // one-sided, so the triangles face inwards, towards the camera. Flat: the walls are diffuse.
  appendSphere(sphere, glm::vec3(0.0f), 1.0f, 16, 32, /*inward=*/true);
  scene.meshes.push_back(std::move(sphere));
  const std::string& object = parameters.text("object");
  if (object != "none") addObject(scene, object);

  scene.camera.position = {0.0f, 0.0f, 0.0f};
  scene.camera.look_at = {0.0f, 0.0f, -1.0f};
  scene.camera.up = {0.0f, 1.0f, 0.0f};
  scene.camera.vertical_fov_deg = 90.0f;
  scene.default_width = 64;
  scene.default_height = 64;
  return scene;
}

}  // namespace gib::scene
