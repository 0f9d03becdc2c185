// The Cornell box as published by the Cornell University Program of Computer Graphics,
// "Cornell Box Data", https://www.graphics.cornell.edu/online/box/data.html: geometry in mm,
// camera, the 130 × 105 mm light, the short and the tall block, and measured spectra (see
// cornell_spectra.cpp) converted to linear Rec.709 by spectrum.cpp; and its variants with a
// mirror and a glass sphere in place of the blocks, and with a spot light in place of the area
// light (docs/scenes.md).
#include "common/input_error.h"
#include "scene/builtin_scenes.h"
#include "scene/cornell_spectra.h"
#include "scene/mesh_builder.h"
#include "scene/metals.h"
#include "scene/spectrum.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace gib::scene {

namespace {

// The published light lies in the ceiling plane (y = 548.8). Lowering it by 0.1 mm keeps the two
// surfaces from being coplanar (which would make which one a ray hits arbitrary) while changing
// the illumination by far less than any error we measure.
constexpr float kLightY = 548.8f - 0.1f;
// The light's published corners span x 213–343 and z 227–332.
constexpr float kLightArea = 130.0f * 105.0f;

// The spheres of the classic "Cornell box with spheres" (the book's colour box, Figs. 6.2 and
// 6.6): by default a mirror sphere at the back on the red wall's side and a glass sphere at the
// front on the green wall's side, both of radius 100 mm standing on the floor. Both lie wholly in
// the camera's view and clear of the walls (the mirror 70 mm from the red wall and 79 mm from the
// back wall, the glass 85 mm from the green wall and 70 mm behind the opening), and the glass
// sphere's caustic under the ceiling light falls on the floor in front of it, about 80 % of it in
// view (rays traced from the light's centre through the sphere, ior 1.5). `mirror_centre` (default
// (380, 100, 380), the position above) moves the mirror sphere, near a wall say, where environment
// mapping's reflections go most wrong (Fig. 6.6).
constexpr float kSphereRadius = 100.0f;
constexpr glm::vec3 kGlassCentre{185.0f, kSphereRadius, 170.0f};
// The centres that keep the mirror sphere inside the box: on or above the floor, under the light
// (y + r ≤ 548.7), inside the right (x = 0) and back (z = 559.2) walls and the opening (z = 0), and
// inside the left wall, which leans in to x = 549.6 at the back of the floor. Whole millimetres.
constexpr glm::vec3 kMirrorCentreMin{100.0f, 100.0f, 100.0f};
constexpr glm::vec3 kMirrorCentreMax{449.0f, 448.0f, 459.0f};
// Fine enough that the facets' silhouette deviates from the sphere by r·(1 − cos(π/128)), 0.03 mm,
// under a tenth of a pixel at the default 512².
constexpr int kSphereRings = 64;
constexpr int kSphereSegments = 128;

// The spot light (light=spot) 1 mm under the ceiling, at the area light's centre.
constexpr glm::vec3 kSpotPosition{278.0f, 548.8f - 1.0f, 279.5f};

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

// The mirror sphere's centre, `mirror_centre`, checked against the box and the glass sphere.
glm::vec3 mirrorCentre(const ParameterValues& parameters, bool with_glass) {
  const std::vector<double> v = parameters.vector3("mirror_centre");
  const glm::vec3 centre{float(v[0]), float(v[1]), float(v[2])};
  const char* axes = "xyz";
  for (int i = 0; i < 3; ++i)
    if (centre[i] < kMirrorCentreMin[i] || centre[i] > kMirrorCentreMax[i])
      throw InputError(fmt::format(
          "scene 'cornell' parameter mirror_centre = '{}' puts the mirror sphere (radius {} mm) "
          "outside the box; give x in [{}, {}], y in [{}, {}], z in [{}, {}] mm ({} is {})",
          parameters.text("mirror_centre"), kSphereRadius, kMirrorCentreMin.x, kMirrorCentreMax.x,
          kMirrorCentreMin.y, kMirrorCentreMax.y, kMirrorCentreMin.z, kMirrorCentreMax.z, axes[i],
          centre[i]));
  if (with_glass && glm::distance(centre, kGlassCentre) < 2.0f * kSphereRadius)
    throw InputError(fmt::format(
        "scene 'cornell' parameter mirror_centre = '{}' puts the mirror sphere into the glass "
        "sphere at ({}, {}, {}) mm; keep the centres at least {} mm apart, or use spheres=mirror",
        parameters.text("mirror_centre"), kGlassCentre.x, kGlassCentre.y, kGlassCentre.z,
        2.0f * kSphereRadius));
  return centre;
}

// The spheres that `spheres` asks for, smooth-shaded.
void addSpheres(Scene& scene, const ParameterValues& parameters) {
  const std::string& spheres = parameters.text("spheres");
  auto addSphere = [&](std::string name, Material material, glm::vec3 centre) {
    appendSphere(addMeshOfMaterial(scene, std::move(name), std::move(material)), centre,
                 kSphereRadius, kSphereRings, kSphereSegments, /*inward=*/false,
                 SphereShading::kSmooth);
  };
  if (spheres == "mirror" || spheres == "mirror_glass")
    addSphere("mirror_sphere", mirrorMaterial("mirror", *findMetal(parameters.text("metal"))),
              mirrorCentre(parameters, spheres == "mirror_glass"));
  if (spheres == "glass" || spheres == "mirror_glass") {
    Material glass;
    glass.name = "glass";
    glass.type = MaterialType::kGlass;
    glass.ior = static_cast<float>(parameters.number("ior"));
    const std::vector<double> absorption = parameters.vector3("absorption");
    glass.absorption = Rgb(float(absorption[0]), float(absorption[1]), float(absorption[2]));
    addSphere("glass_sphere", glass, kGlassCentre);
  }
}

}  // namespace

ParameterTable cornellParameters() {
  return {
      booleanParameter("blocks", true,
                       "the short and the tall block (false: the empty box, whose walls alone "
                       "make a simpler test scene); only with spheres=none, since the spheres "
                       "take the blocks' place"),
      choiceParameter("spheres", "none", {"none", "mirror", "glass", "mirror_glass"},
                      "a mirror sphere (back, red side) and/or a glass sphere (front, green "
                      "side), radius 100 mm, on the floor in place of the blocks"),
      numericParameter("mirror_centre", ParameterType::kVector3, "380,100,380", 100, 459, "mm",
                       "the mirror sphere's centre (spheres=mirror|mirror_glass; Fig. 6.6 moves "
                       "it near a wall): x in [100, 449], y in [100, 448], z in [100, 459], so "
                       "that it stays in the box, on or above the floor, and 200 mm or more from "
                       "the glass sphere's centre (185, 100, 170)"),
      choiceParameter("metal", "silver", metalNames(),
                      "the mirror sphere's metal (docs/scenes.md, \"Metals\"; perfect: R = 1)"),
      numericParameter("ior", ParameterType::kNumber, "1.5", kMinGlassIor, kMaxGlassIor, "",
                       "the glass sphere's index of refraction"),
      numericParameter("absorption", ParameterType::kVector3, "0,0,0", 0, 1, "1/mm",
                       "the glass's Beer-Lambert absorption coefficient per channel"),
      choiceParameter("light", "area", {"area", "spot"},
                      "the ceiling light, or in its place a spot light 1 mm under the ceiling "
                      "pointing down (90° cone, cos fall-off: the same power and distribution "
                      "from a point), whose caustics only light paths reach"),
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
  const Rgb emission = emissionToRec709(cornellLight());
  const bool area_light = parameters.text("light") == "area";

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
  if (area_light) {
    // The page gives the light's emission, not its reflectance; we give it the white paint's.
    const std::uint32_t light_id = addMaterial(scene, "light", white, emission);
    // Wound so that the emitting side faces down, into the box.
    appendQuad(addMesh(scene, "light", light_id), {343.0f, kLightY, 227.0f},
               {343.0f, kLightY, 332.0f}, {213.0f, kLightY, 332.0f}, {213.0f, kLightY, 227.0f});
  } else {
    // A Lambertian emitter of radiance L and area A has the intensity L·A·cos θ (W/sr) seen from
    // afar: a spot of intensity L·A on its axis with a cos¹ fall-off over the whole lower
    // hemisphere sends the same power, π·L·A, the same way. The ceiling quad goes with the
    // emission: the ceiling is white where it was.
    SpotLight spot;
    spot.position = kSpotPosition;
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.intensity = emission * kLightArea;
    spot.cone_angle_deg = 90.0f;
    spot.falloff_exponent = 1.0f;
    scene.spot_lights.push_back(spot);
  }

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
  if (parameters.text("spheres") != "none") {
    addSpheres(scene, parameters);
  } else if (parameters.boolean("blocks")) {
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
