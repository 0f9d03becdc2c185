// The outdoor scene: objects on a ground plane under an environment map, the stage of the book's
// environment-lighting figures (Szirmay-Kalos, Szécsi & Sbert, "GPU-Based Techniques for Global
// Illumination Effects": Figs. 4.9-4.12 and 4.14 of §4.2, Figs. 8.4 and 8.5 of §8.3). The map is
// the built-in clear sky (Preetham et al. 1999, scene/preetham_sky.h) or any latitude–longitude
// EXR the user gives; nothing else lights the scene.
//
// Units are metres; +y is up and the ground is the plane y = 0. The objects stand in a row along
// x, each within 0.5 m of its centre at height 0.5 m: a white Lambertian sphere, a glossy Phong
// sphere, a mirror sphere, a glass sphere and a smooth-shaded torus (the tessellated diffuse
// object of the PRT figures), always the scene's last mesh.
#include "common/input_error.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"
#include "scene/metals.h"
#include "scene/sky_parameters.h"

#include <fmt/format.h>

#include <array>
#include <string>
#include <utility>

namespace gib::scene {

namespace {

// The ground: a square of 100 m, far larger than the view, so that its edge lies near the
// horizon where the sky's own ground (below the horizon) takes over.
constexpr float kGroundHalfWidth = 50.0f;
constexpr float kObjectRadius = 0.5f;
constexpr float kObjectSpacing = 1.3f;  // centre to centre, 0.3 m between neighbours
constexpr int kSphereRings = 32, kSphereSegments = 64;
// The torus: tube 0.15 m around a circle of 0.35 m, leaning back so that its hole shows.
constexpr float kTorusMajorRadius = 0.35f, kTorusMinorRadius = 0.15f;
constexpr int kTorusRings = 64, kTorusSegments = 24;
constexpr glm::vec3 kTorusAxis{0.0f, 1.0f, 0.6f};
// The camera: 7 m in front of the row, a little above it; a 2:1 image with a vertical field of
// 30° shows all five objects, and its top seventh the sky above the horizon.
constexpr glm::vec3 kCameraPosition{0.0f, 1.5f, 7.0f};
constexpr glm::vec3 kCameraLookAt{0.0f, 0.6f, 0.0f};
constexpr float kCameraFovDeg = 30.0f;

Material lambert(std::string name, Rgb diffuse) {
  Material m;
  m.name = std::move(name);
  m.type = MaterialType::kLambert;
  m.diffuse = diffuse;
  return m;
}

// Normalised modified Phong (scene/scene.h), a shininess of 20: a glossy highlight that the
// pre-convolved glossy maps of Fig. 4.12 resolve, over a dark diffuse base, 0.2 + 0.6 ≤ 1.
Material glossy() {
  Material m = lambert("glossy", Rgb(0.2f));
  m.type = MaterialType::kPhong;
  m.specular = Rgb(0.6f);
  m.exponent = 20.0f;
  return m;
}

Material glass() {
  Material m;
  m.name = "glass";
  m.type = MaterialType::kGlass;
  m.ior = 1.5f;
  return m;
}

void addSphere(Scene& scene, std::string name, Material material, glm::vec3 centre) {
  appendSphere(addMeshOfMaterial(scene, std::move(name), std::move(material)), centre,
               kObjectRadius, kSphereRings, kSphereSegments, /*inward=*/false,
               SphereShading::kSmooth);
}

void addObjects(Scene& scene, const std::string& which) {
  const std::array<std::string, 5> kinds = {"diffuse", "glossy", "mirror", "glass", "torus"};
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    const std::string& kind = kinds[i];
    if (which != "all" && which != kind) continue;
    // Alone, an object stands in the middle; in the row, in the order above from left to right.
    const float x = which == "all" ? (float(i) - 2.0f) * kObjectSpacing : 0.0f;
    const glm::vec3 centre{x, kObjectRadius, 0.0f};
    if (kind == "diffuse")
      addSphere(scene, "diffuse_sphere", lambert("white", Rgb(0.8f)), centre);
    else if (kind == "glossy")
      addSphere(scene, "glossy_sphere", glossy(), centre);
    else if (kind == "mirror")
      addSphere(scene, "mirror_sphere", mirrorMaterial("silver", *findMetal("silver")), centre);
    else if (kind == "glass")
      addSphere(scene, "glass_sphere", glass(), centre);
    else
      appendTorus(addMeshOfMaterial(scene, "torus", lambert("torus", Rgb(0.7f))), centre,
                  kTorusAxis, kTorusMajorRadius, kTorusMinorRadius, kTorusRings, kTorusSegments);
  }
}

}  // namespace

ParameterTable outdoorParameters() {
  return joinParameterTables({
      {choiceParameter("objects", "all", {"all", "diffuse", "glossy", "mirror", "glass", "torus"},
                       "what stands on the ground: the row of a white Lambertian sphere, a glossy "
                       "Phong sphere (0.2 + 0.6, shininess 20), a silver mirror sphere, a glass "
                       "sphere (index 1.5) and a grey torus, or one of them alone in the middle")},
      skyParameters({"30", "120",
                     "(the camera looks along -z; 120 puts the sun behind the camera, to its "
                     "left)"}),
  });
}

Scene makeOutdoor(const ParameterValues& parameters) {
  Scene scene;
  scene.name = "outdoor";
  scene.provenance =
      "procedural ground and objects under an environment map after Szirmay-Kalos et al. §4.2 "
      "(Figs. 4.9-4.12, 4.14) and §8.3 (Figs. 8.4, 8.5)";
  const float g = kGroundHalfWidth;
  appendQuad(addMeshOfMaterial(scene, "ground", lambert("ground", Rgb(0.5f))), {-g, 0, -g},
             {-g, 0, g}, {g, 0, g}, {g, 0, -g});
  addObjects(scene, parameters.text("objects"));
  scene.environment = makeSkyEnvironment(parameters, "outdoor");

  scene.camera.position = kCameraPosition;
  scene.camera.look_at = kCameraLookAt;
  scene.camera.up = {0.0f, 1.0f, 0.0f};
  scene.camera.vertical_fov_deg = kCameraFovDeg;
  scene.default_width = 512;
  scene.default_height = 256;
  return scene;
}

}  // namespace gib::scene
