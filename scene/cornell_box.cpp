// The Cornell box as published by the Cornell University Program of Computer Graphics,
// "Cornell Box Data", https://www.graphics.cornell.edu/online/box/data.html: geometry in mm,
// camera, the 130 × 105 mm light, the short and the tall block, and measured spectra (see
// cornell_spectra.cpp) converted to linear Rec.709 by spectrum.cpp.
#include "scene/builtin_scenes.h"
#include "scene/cornell_spectra.h"
#include "scene/mesh_builder.h"
#include "scene/spectrum.h"

#include <glm/trigonometric.hpp>

#include <cmath>

namespace gib::scene {

namespace {

// The published light lies in the ceiling plane (y = 548.8). Lowering it by 0.1 mm keeps the two
// surfaces from being coplanar (which would make which one a ray hits arbitrary) while changing
// the illumination by far less than any error we measure.
constexpr float kLightY = 548.8f - 0.1f;

std::uint32_t addMaterial(Scene& scene, std::string name, Rgb diffuse, Rgb emission = Rgb(0.0f)) {
  Material m;
  m.name = std::move(name);
  m.type = MaterialType::kLambert;
  m.diffuse = diffuse;
  m.emission = emission;
  scene.materials.push_back(m);
  return static_cast<std::uint32_t>(scene.materials.size() - 1);
}

Mesh& addMesh(Scene& scene, std::string name, std::uint32_t material) {
  Mesh mesh;
  mesh.name = std::move(name);
  mesh.material = material;
  scene.meshes.push_back(std::move(mesh));
  return scene.meshes.back();
}

// A block: its top quad and the four side quads, each given as the published four corners.
void addBlock(Mesh& mesh, const glm::vec3 (&quads)[5][4]) {
  for (const auto& q : quads) appendQuad(mesh, q[0], q[1], q[2], q[3]);
}

}  // namespace

ParameterTable cornellParameters() {
  return {
      booleanParameter("blocks", true,
                       "the short and the tall block (false: the empty box, whose walls alone "
                       "make a simpler test scene)"),
  };
}

Scene makeCornellBox(const ParameterValues& parameters) {
  Scene scene;
  scene.name = "cornell";
  scene.provenance =
      "Cornell Box Data, Cornell University Program of Computer Graphics "
      "(https://www.graphics.cornell.edu/online/box/data.html); spectra to Rec.709 under D65 "
      "with the CIE 1931 2-degree observer; light lowered 0.1 mm below the ceiling";

  const Rgb white = reflectanceToRec709(cornellWhite());
  const std::uint32_t white_id = addMaterial(scene, "white", white);
  const std::uint32_t green_id = addMaterial(scene, "green", reflectanceToRec709(cornellGreen()));
  const std::uint32_t red_id = addMaterial(scene, "red", reflectanceToRec709(cornellRed()));
  // The page gives the light's emission, not its reflectance; we give it the white paint's.
  const std::uint32_t light_id =
      addMaterial(scene, "light", white, emissionToRec709(cornellLight()));

  appendQuad(addMesh(scene, "floor", white_id), {552.8f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f},
             {0.0f, 0.0f, 559.2f}, {549.6f, 0.0f, 559.2f});
  appendQuad(addMesh(scene, "ceiling", white_id), {556.0f, 548.8f, 0.0f}, {556.0f, 548.8f, 559.2f},
             {0.0f, 548.8f, 559.2f}, {0.0f, 548.8f, 0.0f});
  appendQuad(addMesh(scene, "back_wall", white_id), {549.6f, 0.0f, 559.2f}, {0.0f, 0.0f, 559.2f},
             {0.0f, 548.8f, 559.2f}, {556.0f, 548.8f, 559.2f});
  appendQuad(addMesh(scene, "right_wall", green_id), {0.0f, 0.0f, 559.2f}, {0.0f, 0.0f, 0.0f},
             {0.0f, 548.8f, 0.0f}, {0.0f, 548.8f, 559.2f});
  appendQuad(addMesh(scene, "left_wall", red_id), {552.8f, 0.0f, 0.0f}, {549.6f, 0.0f, 559.2f},
             {556.0f, 548.8f, 559.2f}, {556.0f, 548.8f, 0.0f});
  // Wound so that the emitting side faces down, into the box.
  appendQuad(addMesh(scene, "light", light_id), {343.0f, kLightY, 227.0f},
             {343.0f, kLightY, 332.0f}, {213.0f, kLightY, 332.0f}, {213.0f, kLightY, 227.0f});

  static const glm::vec3 kShortBlock[5][4] = {{{130.0f, 165.0f, 65.0f},
                                               {82.0f, 165.0f, 225.0f},
                                               {240.0f, 165.0f, 272.0f},
                                               {290.0f, 165.0f, 114.0f}},
                                              {{290.0f, 0.0f, 114.0f},
                                               {290.0f, 165.0f, 114.0f},
                                               {240.0f, 165.0f, 272.0f},
                                               {240.0f, 0.0f, 272.0f}},
                                              {{130.0f, 0.0f, 65.0f},
                                               {130.0f, 165.0f, 65.0f},
                                               {290.0f, 165.0f, 114.0f},
                                               {290.0f, 0.0f, 114.0f}},
                                              {{82.0f, 0.0f, 225.0f},
                                               {82.0f, 165.0f, 225.0f},
                                               {130.0f, 165.0f, 65.0f},
                                               {130.0f, 0.0f, 65.0f}},
                                              {{240.0f, 0.0f, 272.0f},
                                               {240.0f, 165.0f, 272.0f},
                                               {82.0f, 165.0f, 225.0f},
                                               {82.0f, 0.0f, 225.0f}}};
  static const glm::vec3 kTallBlock[5][4] = {{{423.0f, 330.0f, 247.0f},
                                              {265.0f, 330.0f, 296.0f},
                                              {314.0f, 330.0f, 456.0f},
                                              {472.0f, 330.0f, 406.0f}},
                                             {{423.0f, 0.0f, 247.0f},
                                              {423.0f, 330.0f, 247.0f},
                                              {472.0f, 330.0f, 406.0f},
                                              {472.0f, 0.0f, 406.0f}},
                                             {{472.0f, 0.0f, 406.0f},
                                              {472.0f, 330.0f, 406.0f},
                                              {314.0f, 330.0f, 456.0f},
                                              {314.0f, 0.0f, 456.0f}},
                                             {{314.0f, 0.0f, 456.0f},
                                              {314.0f, 330.0f, 456.0f},
                                              {265.0f, 330.0f, 296.0f},
                                              {265.0f, 0.0f, 296.0f}},
                                             {{265.0f, 0.0f, 296.0f},
                                              {265.0f, 330.0f, 296.0f},
                                              {423.0f, 330.0f, 247.0f},
                                              {423.0f, 0.0f, 247.0f}}};
  if (parameters.boolean("blocks")) {
    addBlock(addMesh(scene, "short_block", white_id), kShortBlock);
    addBlock(addMesh(scene, "tall_block", white_id), kTallBlock);
  }

  // Focal length 35 mm on a 25 × 25 mm film: vertical field of view 2·atan(12.5/35) ≈ 39.3077°.
  scene.camera.position = {278.0f, 273.0f, -800.0f};
  scene.camera.look_at = {278.0f, 273.0f, 0.0f};
  scene.camera.up = {0.0f, 1.0f, 0.0f};
  scene.camera.vertical_fov_deg = float(glm::degrees(2.0 * std::atan(12.5 / 35.0)));
  scene.default_width = 512;
  scene.default_height = 512;
  return scene;
}

}  // namespace gib::scene
