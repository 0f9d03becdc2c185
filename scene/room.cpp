// The room: a closed cubic room lit by "fire balls", with one diffuse or glossy object in it, after
// the room of Szirmay-Kalos, Szécsi & Sbert, "GPU-Based Techniques for Global Illumination
// Effects", §7.3 (Figs. 7.10-7.13): the scene in which the book compares diffuse and glossy
// environment mapping with its distance-map final gathering. The walls have distinct colours, so
// the light an object gathers changes with where it stands (what the classical environment map,
// taken at one reference point, cannot show). A smooth sphere or torus stands in for the book's
// skull, bunny, Buddha and dragon.
//
// Units are metres. The room spans x in [-2, 2], y in [0, 4] (floor at 0), z in [-2, 2]. The
// object is the scene's LAST mesh: a technique that gathers onto one object takes the last mesh
// by default (docs/scenes.md).
#include "common/input_error.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace gib::scene {

namespace {

constexpr float kHalfWidth = 2.0f;  // walls at x = ±2 and z = ±2
constexpr float kHeight = 4.0f;     // ceiling at y = 4

// The object: a sphere of radius 0.5 m, or a torus whose tube (0.15 m) sweeps a circle of 0.35 m,
// so that both fit the same ball of 0.5 m. Tessellated finely enough to look round when smooth
// shaded, and lightly enough (about 4 000 and 3 000 triangles) for the techniques that treat
// every triangle.
constexpr float kObjectRadius = 0.5f;
constexpr int kSphereRings = 32, kSphereSegments = 64;
constexpr float kTorusMajorRadius = 0.35f, kTorusMinorRadius = 0.15f;
constexpr int kTorusRings = 64, kTorusSegments = 24;
// The torus leans back from the camera, so that its hole and the room behind it show.
constexpr glm::vec3 kTorusAxis{0.0f, 0.5f, 1.0f};
// Clearance kept between the object and the walls, fire balls and camera (no touching surfaces).
constexpr float kClearance = 0.05f;

// The fire balls: small warm spheres of emissive triangles, two at the back of the room in view
// and two behind the camera lighting the object's front, at least 0.5 m from every wall and
// 1.7 m from the default object. Radiance (60, 44, 28): warm, but white enough that the walls
// keep their colours; the middle of the default object then has a radiance of about 0.2 from the
// balls directly and 0.5 with the walls' bounces (luminance, measured with the reference), bright
// but not clipped by the display transform at exposure 0.
constexpr float kFireBallRadius = 0.15f;
constexpr int kFireBallRings = 6, kFireBallSegments = 12;  // 120 emissive triangles each
constexpr Rgb kFireEmission{60.0f, 44.0f, 28.0f};
constexpr std::array<glm::vec3, 4> kFireBalls = {{
    {-1.3f, 3.0f, -1.2f},
    {1.3f, 2.4f, -1.3f},
    {1.3f, 0.7f, 1.1f},
    {-1.2f, 1.2f, 1.3f},
}};

// Near the wall the object is not in (z = 2), a little above the default object, looking at it.
constexpr glm::vec3 kCameraPosition{0.0f, 2.0f, 1.9f};
constexpr glm::vec3 kCameraLookAt{0.0f, 1.5f, 0.0f};
constexpr float kCameraFovDeg = 60.0f;

Material lambert(std::string name, Rgb diffuse) {
  Material m;
  m.name = std::move(name);
  m.type = MaterialType::kLambert;
  m.diffuse = diffuse;
  return m;
}

// The six walls, each a quad of its own colour facing into the room, sharing the cube's corners
// exactly: the room is closed. Reflectances by eye, at most 0.75, so that light dies out.
void addWalls(Scene& scene) {
  const float w = kHalfWidth, h = kHeight;
  const glm::vec3 p000(-w, 0, -w), p100(w, 0, -w), p010(-w, h, -w), p110(w, h, -w);
  const glm::vec3 p001(-w, 0, w), p101(w, 0, w), p011(-w, h, w), p111(w, h, w);
  auto wall = [&](std::string name, Rgb colour, glm::vec3 a, glm::vec3 b, glm::vec3 c,
                  glm::vec3 d) {
    appendQuad(addMeshOfMaterial(scene, name, lambert(name, colour)), a, b, c, d);
  };
  wall("floor", Rgb(0.7f), p000, p001, p101, p100);
  wall("ceiling", Rgb(0.75f), p010, p110, p111, p011);
  wall("red_wall", {0.75f, 0.15f, 0.12f}, p000, p010, p011, p001);   // x = −2, image left
  wall("green_wall", {0.15f, 0.6f, 0.15f}, p100, p101, p111, p110);  // x = +2, image right
  wall("blue_wall", {0.15f, 0.25f, 0.75f}, p000, p100, p110, p010);  // z = −2, facing the camera
  wall("yellow_wall", {0.75f, 0.7f, 0.2f}, p001, p011, p111, p101);  // z = +2, behind the camera
}

// One emissive material for all the balls, each ball its own mesh (its own light).
void addFireBalls(Scene& scene) {
  Material fire = lambert("fire", Rgb(0.0f));
  fire.emission = kFireEmission;
  scene.materials.push_back(fire);
  for (std::size_t i = 0; i < kFireBalls.size(); ++i) {
    Mesh ball;
    ball.name = fmt::format("fire_ball_{}", i);
    ball.material = static_cast<std::uint32_t>(scene.materials.size() - 1);
    appendSphere(ball, kFireBalls[i], kFireBallRadius, kFireBallRings, kFireBallSegments,
                 /*inward=*/false);
    scene.meshes.push_back(std::move(ball));
  }
}

// `object_position`, checked: the object inside the room, clear of the fire balls and the camera.
glm::vec3 objectPosition(const ParameterValues& parameters) {
  const std::vector<double> v = parameters.vector3("object_position");
  const glm::vec3 p{float(v[0]), float(v[1]), float(v[2])};
  const std::string& text = parameters.text("object_position");
  const float reach = kObjectRadius + kClearance;
  if (std::abs(p.x) > kHalfWidth - reach || std::abs(p.z) > kHalfWidth - reach || p.y < reach ||
      p.y > kHeight - reach)
    throw InputError(fmt::format(
        "scene 'room' parameter object_position = '{}' puts the object (radius {} m) into a wall; "
        "give x and z in [{:.2f}, {:.2f}] and y in [{:.2f}, {:.2f}] m",
        text, kObjectRadius, -(kHalfWidth - reach), kHalfWidth - reach, reach, kHeight - reach));
  for (const glm::vec3& ball : kFireBalls)
    if (glm::distance(p, ball) < reach + kFireBallRadius)
      throw InputError(fmt::format(
          "scene 'room' parameter object_position = '{}' puts the object into the fire ball at "
          "({}, {}, {}); keep its centre at least {:.2f} m from it",
          text, ball.x, ball.y, ball.z, reach + kFireBallRadius));
  if (glm::distance(p, kCameraPosition) < reach)
    throw InputError(fmt::format(
        "scene 'room' parameter object_position = '{}' puts the object around the camera at "
        "({}, {}, {}); keep its centre at least {:.2f} m from it",
        text, kCameraPosition.x, kCameraPosition.y, kCameraPosition.z, reach));
  return p;
}

Material objectMaterial(const std::string& kind) {
  if (kind == "diffuse") return lambert("diffuse_grey", Rgb(0.7f));
  // The normalised modified Phong of docs/architecture.md, "Materials", with the book's shininess
  // 5 (Figs. 7.12 and 7.13): a broad glossy lobe over a darker diffuse base, 0.25 + 0.6 ≤ 1.
  Material m = lambert("glossy_grey", Rgb(0.25f));
  m.type = MaterialType::kPhong;
  m.specular = Rgb(0.6f);
  m.exponent = 5.0f;
  return m;
}

void addObject(Scene& scene, const ParameterValues& parameters) {
  const glm::vec3 centre = objectPosition(parameters);
  const std::string& shape = parameters.text("shape");
  Mesh& mesh =
      addMeshOfMaterial(scene, "object_" + shape, objectMaterial(parameters.text("object")));
  if (shape == "sphere")
    appendSphere(mesh, centre, kObjectRadius, kSphereRings, kSphereSegments, /*inward=*/false,
                 SphereShading::kSmooth);
  else
    appendTorus(mesh, centre, kTorusAxis, kTorusMajorRadius, kTorusMinorRadius, kTorusRings,
                kTorusSegments);
}

}  // namespace

ParameterTable roomParameters() {
  return {
      choiceParameter("object", "diffuse", {"diffuse", "glossy"},
                      "the object's material: Lambert grey 0.7 (Fig. 7.11), or normalised Phong "
                      "with diffuse 0.25, specular 0.6 and shininess 5 (Figs. 7.12, 7.13)"),
      choiceParameter("shape", "sphere", {"sphere", "torus"},
                      "the object, smooth-shaded, within 0.5 m of its centre: a sphere of radius "
                      "0.5 m or a torus (0.35 m around, tube 0.15 m), standing in for the book's "
                      "skull, bunny, Buddha and dragon; always the scene's last mesh"),
      numericParameter("object_position", ParameterType::kVector3, "0,1.5,0", -1.45, 3.45, "m",
                       "the object's centre: x and z in [-1.45, 1.45], y in [0.55, 3.45] (inside "
                       "the room), 0.7 m or more from each fire ball's centre and 0.55 m from the "
                       "camera at (0, 2, 1.9)"),
  };
}

Scene makeRoom(const ParameterValues& parameters) {
  Scene scene;
  scene.name = "room";
  scene.provenance =
      "procedural cubic room lit by fire balls after Szirmay-Kalos et al. §7.3, Figs. 7.10-7.13; "
      "a sphere or torus in place of the book's skull, bunny, Buddha and dragon";
  addWalls(scene);
  addFireBalls(scene);
  addObject(scene, parameters);  // last: the object a technique gathers onto by default

  scene.camera.position = kCameraPosition;
  scene.camera.look_at = kCameraLookAt;
  scene.camera.up = {0.0f, 1.0f, 0.0f};
  scene.camera.vertical_fov_deg = kCameraFovDeg;
  scene.default_width = 512;
  scene.default_height = 512;
  return scene;
}

}  // namespace gib::scene
