#include "common/input_error.h"
#include "common/parameters.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"
#include "scene/metals.h"
#include "support/mesh_topology.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace gib::scene {
namespace {

// Guards against accidental changes to the chamber's geometry, materials, light or camera: stored
// references are keyed by the scene hash, so a change must be deliberate. Update it together with
// whatever changed the scene (and say so in the change).
constexpr const char* kDefaultChamberHash = "0014adf7eceaa1f5e736db38e03529d5";

// The hall's interior (metres, chamber.cpp): x in [−4, 4], y in [0, 7.2], z in [0, 12]; the nave's
// vault turns about the axis x = 0, y = 5.
constexpr float kHalfWidth = 4.0f, kCrownY = 7.2f, kLength = 12.0f, kVaultAxisY = 5.0f;
// Where the arches spring, on the capitals.
constexpr float kSpringY = 3.0f;
// Smallest triangle area we accept (m²); the smallest at detail 5 is about 10⁻³ m².
constexpr float kMinTriangleArea = 1e-6f;

ParameterValues chamberValues(const std::vector<std::string>& assignments = {}) {
  return parseParameters(chamberParameters(), assignments, "scene 'chamber'");
}

Scene chamberAt(int detail) {
  return makeChamber(chamberValues({"detail=" + std::to_string(detail)}));
}

glm::vec3 triangleNormal(const Mesh& mesh, const glm::uvec3& t) {
  const glm::vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
  return glm::cross(b - a, c - a);
}

glm::vec3 centroid(const Mesh& mesh, const glm::uvec3& t) {
  return (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0f;
}

const Mesh& meshNamed(const Scene& scene, const std::string& name) {
  for (const Mesh& mesh : scene.meshes)
    if (mesh.name == name) return mesh;
  throw std::runtime_error("the chamber has no mesh '" + name + "'");
}

TEST(Chamber, TriangleCountGrowsWithDetail) {
  // The targets: about 3 300 triangles by default (the book's chamber has 3335), about
  // 80 000 at the highest detail (the art-gallery scale). Counts: 3384, 13600, 30648, 54528, 85240.
  std::size_t previous = 0;
  for (int detail = 1; detail <= 5; ++detail) {
    const std::size_t count = chamberAt(detail).triangleCount();
    EXPECT_GT(count, previous) << "detail " << detail;
    previous = count;
  }
  const std::size_t by_default = makeChamber(chamberValues()).triangleCount();
  EXPECT_GE(by_default, 3000u);
  EXPECT_LE(by_default, 3600u);
  const std::size_t at_most = chamberAt(5).triangleCount();
  EXPECT_GE(at_most, 60000u);
  EXPECT_LE(at_most, 100000u);
}

TEST(Chamber, SameTrianglesOnEveryMachine) {
  const Scene scene = makeChamber(chamberValues());
  EXPECT_EQ(hashScene(scene), hashScene(makeChamber(chamberValues())));
  EXPECT_EQ(hashScene(scene), kDefaultChamberHash);
  EXPECT_EQ(scene.name, "chamber");
  EXPECT_NE(scene.provenance.find("Fig. 8.12"), std::string::npos);
}

TEST(Chamber, IsValidAtEveryDetail) {
  for (int detail = 1; detail <= 5; ++detail)
    EXPECT_NO_THROW(validateScene(chamberAt(detail))) << "detail " << detail;
}

TEST(Chamber, HasNoDegenerateTriangles) {
  for (int detail = 1; detail <= 5; ++detail) {
    const Scene scene = chamberAt(detail);
    std::size_t degenerate = 0;
    for (const Mesh& mesh : scene.meshes)
      for (const glm::uvec3& t : mesh.triangles)
        if (0.5f * glm::length(triangleNormal(mesh, t)) <= kMinTriangleArea) ++degenerate;
    EXPECT_EQ(degenerate, 0u) << "detail " << detail;
  }
}

TEST(Chamber, StaysInsideTheHall) {
  constexpr float kSlack = 1e-4f;
  for (const Scene& scene :
       {chamberAt(2), makeChamber(chamberValues({"detail=2", "specular=objects"}))})
    for (const Mesh& mesh : scene.meshes)
      for (const glm::vec3& p : mesh.positions) {
        ASSERT_LE(std::abs(p.x), kHalfWidth + kSlack) << mesh.name;
        ASSERT_GE(p.y, -kSlack) << mesh.name;
        ASSERT_LE(p.y, kCrownY + kSlack) << mesh.name;
        ASSERT_GE(p.z, -kSlack) << mesh.name;
        ASSERT_LE(p.z, kLength + kSlack) << mesh.name;
      }
}

TEST(Chamber, ShellFacesIntoTheHall) {
  // The floor, walls, end walls and vault face the hall's centre line, a segment along the
  // vault's axis (kept short of the end walls, so that the end walls see it in front of them);
  // the aisle ceilings, lower than that axis, face down.
  const Scene scene = chamberAt(2);
  for (const char* name :
       {"floor", "wainscot", "aisle_walls", "end_walls", "lunettes", "vault", "arcade_walls"}) {
    std::size_t wrong = 0;
    const Mesh& mesh = meshNamed(scene, name);
    ASSERT_FALSE(mesh.triangles.empty()) << name;
    for (const glm::uvec3& t : mesh.triangles) {
      const glm::vec3 c = centroid(mesh, t);
      const glm::vec3 on_axis(0.0f, kVaultAxisY, std::clamp(c.z, 0.5f, kLength - 0.5f));
      glm::vec3 towards = on_axis - c;
      // Each arcade wall has two faces; the aisle face looks away from the nave, out at the
      // aisle wall.
      if (std::string(name) == "arcade_walls" && std::abs(c.x) > 2.5f)
        towards = glm::vec3(c.x, 0.0f, 0.0f);
      if (glm::dot(triangleNormal(mesh, t), towards) <= 0) ++wrong;
    }
    EXPECT_EQ(wrong, 0u) << name;
  }
  for (const glm::uvec3& t : meshNamed(scene, "aisle_ceilings").triangles)
    EXPECT_LT(triangleNormal(meshNamed(scene, "aisle_ceilings"), t).y, 0.0f);
  // Pillar shafts face away from their own axis (x = ±2.5).
  const Mesh& shafts = meshNamed(scene, "pillar_shafts");
  for (const glm::uvec3& t : shafts.triangles) {
    const glm::vec3 c = centroid(shafts, t);
    const float axis_x = c.x < 0 ? -2.5f : 2.5f;
    const float z = std::round(c.z / 2.4f) * 2.4f;
    EXPECT_GT(glm::dot(triangleNormal(shafts, t), glm::vec3(c.x - axis_x, 0.0f, c.z - z)), 0.0f);
  }
}

TEST(Chamber, MaterialsAreMarbleLike) {
  const Scene scene = makeChamber(chamberValues());
  const Material& floor = scene.materials.at(meshNamed(scene, "floor").material);
  const Material& walls = scene.materials.at(meshNamed(scene, "aisle_walls").material);
  const Material& pillars = scene.materials.at(meshNamed(scene, "pillar_shafts").material);
  // A darker, slightly glossy floor under light walls and pillars of two different marbles.
  EXPECT_EQ(floor.type, MaterialType::kPhong);
  EXPECT_GT(luminance(floor.specular), 0.0f);
  EXPECT_LT(luminance(floor.diffuse + floor.specular), 0.5f);
  EXPECT_GT(luminance(walls.diffuse), 0.6f);
  EXPECT_GT(luminance(pillars.diffuse), 0.6f);
  EXPECT_NE(walls.diffuse, pillars.diffuse);
  // Coloured marble for colour bleeding: some material's channels differ by a factor of two.
  int coloured = 0;
  for (const Material& m : scene.materials) {
    const float lo = std::min({m.diffuse.r, m.diffuse.g, m.diffuse.b});
    const float hi = std::max({m.diffuse.r, m.diffuse.g, m.diffuse.b});
    if (hi > 2.0f * lo) ++coloured;
    EXPECT_FALSE(m.isEmissive()) << m.name;
    EXPECT_FALSE(m.name.empty());
  }
  EXPECT_GE(coloured, 1);
}

TEST(Chamber, SpotLightAimsAtTheFloorAndFollowsItsParameters) {
  const Scene scene = makeChamber(chamberValues());
  ASSERT_EQ(scene.spot_lights.size(), 1u);
  const SpotLight& spot = scene.spot_lights[0];
  EXPECT_LT(spot.direction.y, 0.0f);
  EXPECT_NEAR(glm::length(spot.direction), 1.0f, 1e-6f);
  // Its axis meets the floor (y = 0) inside the nave.
  const glm::vec3 on_floor = spot.position - (spot.position.y / spot.direction.y) * spot.direction;
  EXPECT_LT(std::abs(on_floor.x), 2.2f);
  EXPECT_GT(on_floor.z, 0.0f);
  EXPECT_LT(on_floor.z, kLength);
  EXPECT_GT(spot.position.y, 0.0f);
  EXPECT_LT(spot.position.y, kCrownY);

  const Scene moved = makeChamber(
      chamberValues({"light_position=1,5,2", "light_target=1,0,6", "light_intensity=123"}));
  const SpotLight& m = moved.spot_lights.at(0);
  EXPECT_EQ(m.position, glm::vec3(1, 5, 2));
  EXPECT_NEAR(glm::dot(m.direction, glm::normalize(glm::vec3(0, -5, 4))), 1.0f, 1e-6f);
  EXPECT_EQ(m.intensity, Rgb(123.0f));
  EXPECT_NE(hashScene(moved), hashScene(scene));
  // Moving the light leaves the geometry alone.
  EXPECT_EQ(moved.triangleCount(), scene.triangleCount());
}

TEST(Chamber, CameraSeesTheLitFloor) {
  const Scene scene = makeChamber(chamberValues());
  const SpotLight& spot = scene.spot_lights.at(0);
  const glm::vec3 lit = spot.position - (spot.position.y / spot.direction.y) * spot.direction;
  const CameraFrame f = makeCameraFrame(scene.camera, scene.default_width, scene.default_height);
  // Project the centre of the lit spot into the image: it must fall inside the frame.
  const glm::vec3 v = lit - f.origin;
  const float depth = glm::dot(v, f.forward);
  ASSERT_GT(depth, 0.0f);
  EXPECT_LT(std::abs(glm::dot(v, f.right) / depth), f.tan_half_fov_y * f.aspect);
  EXPECT_LT(std::abs(glm::dot(v, f.up) / depth), f.tan_half_fov_y);
  // The camera stands inside the hall, at eye height.
  EXPECT_LT(std::abs(scene.camera.position.x), kHalfWidth);
  EXPECT_GT(scene.camera.position.z, 0.0f);
  EXPECT_NEAR(scene.camera.position.y, 1.7f, 0.3f);
}

TEST(Chamber, RejectsBadParameters) {
  for (const char* bad :
       {"detail=9", "detail=0", "detail=1.5", "light_intensity=-1", "light_position=0,1",
        "light_target=0,0,nan", "lamp=1", "specular=teapot"})
    EXPECT_THROW(chamberValues({bad}), InputError) << bad;
  // A light at its own target has no direction.
  EXPECT_THROW(makeChamber(chamberValues({"light_position=1,2,3", "light_target=1,2,3"})),
               InputError);
}

// specular=objects (book Figs. 6.9 and 6.11): the objects' meshes, by name.
constexpr const char* kSpecularObjects[] = {"aluminium_torus", "glass_sphere", "glass_pane",
                                            "mirror_panel"};
// The nave's free floor: inside the plinths' faces (x = ±2.1) and the responds (0.35 m from the
// end walls); objects keep clear of it by this much.
constexpr float kNaveFreeHalfWidth = 2.1f, kRespondDepth = 0.35f;

TEST(Chamber, SpecularObjectsKeepTheDefaultScene) {
  const Scene plain = makeChamber(chamberValues({"specular=none"}));
  EXPECT_EQ(hashScene(plain), kDefaultChamberHash);
  EXPECT_FALSE(plain.hasIdealSpecular());
  const Scene with = makeChamber(chamberValues({"specular=objects"}));
  EXPECT_NE(hashScene(with), kDefaultChamberHash);
  // The chamber itself is unchanged: the objects come after its meshes.
  ASSERT_EQ(with.meshes.size(), plain.meshes.size() + std::size(kSpecularObjects));
  for (std::size_t i = 0; i < plain.meshes.size(); ++i) {
    EXPECT_EQ(with.meshes[i].name, plain.meshes[i].name);
    EXPECT_EQ(with.meshes[i].positions, plain.meshes[i].positions);
  }
  EXPECT_NO_THROW(validateScene(with));
}

TEST(Chamber, SpecularObjectsAreIdealMirrorsAndGlass) {
  const Scene scene = makeChamber(chamberValues({"specular=objects"}));
  EXPECT_TRUE(scene.hasIdealSpecular());
  const Material& teapot = scene.materials.at(meshNamed(scene, "aluminium_torus").material);
  EXPECT_EQ(teapot.type, MaterialType::kMirror);
  EXPECT_EQ(teapot.conductor_n, findMetal("aluminium")->n);
  EXPECT_EQ(teapot.conductor_k, findMetal("aluminium")->k);
  const Material& skull = scene.materials.at(meshNamed(scene, "glass_sphere").material);
  EXPECT_EQ(skull.type, MaterialType::kGlass);
  EXPECT_FLOAT_EQ(skull.ior, 1.3f) << "Fig. 6.9's glass skull";
  EXPECT_EQ(scene.materials.at(meshNamed(scene, "glass_pane").material).type, MaterialType::kGlass);
  EXPECT_EQ(scene.materials.at(meshNamed(scene, "mirror_panel").material).type,
            MaterialType::kMirror);
  // Each object its own material; the curved ones smooth-shaded.
  std::vector<std::uint32_t> materials;
  for (const char* name : kSpecularObjects) materials.push_back(meshNamed(scene, name).material);
  std::sort(materials.begin(), materials.end());
  EXPECT_EQ(std::unique(materials.begin(), materials.end()), materials.end());
  for (const char* name : {"aluminium_torus", "glass_sphere"})
    EXPECT_EQ(meshNamed(scene, name).normals.size(), meshNamed(scene, name).positions.size())
        << name;
  // The pane and the panel are thin: a few centimetres between their large faces.
  for (const char* name : {"glass_pane", "mirror_panel"}) {
    const Mesh& slab = meshNamed(scene, name);
    const double volume = test::signedVolume({&slab});
    EXPECT_GT(volume, 0.0) << name;
    EXPECT_LT(volume, 1.0 * 1.4 * 0.05) << name;
  }
}

TEST(Chamber, SpecularObjectsAreClosedAndFaceOutwards) {
  const Scene scene = makeChamber(chamberValues({"specular=objects"}));
  for (const char* name : kSpecularObjects) {
    const Mesh& mesh = meshNamed(scene, name);
    EXPECT_EQ(test::unmatchedEdges({&mesh}), 0u) << name << ": every edge between two triangles";
    EXPECT_GT(test::signedVolume({&mesh}), 0.0) << name << " faces outwards";
  }
}

TEST(Chamber, SpecularObjectsStandOnTheNaveFloorInView) {
  const Scene scene = makeChamber(chamberValues({"specular=objects"}));
  const CameraFrame f = makeCameraFrame(scene.camera, scene.default_width, scene.default_height);
  std::vector<std::pair<glm::vec3, glm::vec3>> bounds;
  for (const char* name : kSpecularObjects) {
    const Mesh& mesh = meshNamed(scene, name);
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : mesh.positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
      // In view: every vertex projects inside the image.
      const glm::vec3 v = p - f.origin;
      const float depth = glm::dot(v, f.forward);
      ASSERT_GT(depth, 0.0f) << name;
      EXPECT_LT(std::abs(glm::dot(v, f.right) / depth), f.tan_half_fov_y * f.aspect) << name;
      EXPECT_LT(std::abs(glm::dot(v, f.up) / depth), f.tan_half_fov_y) << name;
    }
    // On the floor, not in it, and clear of the plinths, pillars, end walls and the spot light.
    EXPECT_GT(lo.y, 0.0f) << name;
    EXPECT_LT(lo.y, 0.01f) << name << " stands on the floor";
    EXPECT_LT(hi.y, kSpringY) << name;
    EXPECT_LT(std::max(std::abs(lo.x), std::abs(hi.x)), kNaveFreeHalfWidth - 0.2f) << name;
    EXPECT_GT(lo.z, kRespondDepth) << name;
    EXPECT_LT(hi.z, kLength - kRespondDepth) << name;
    bounds.emplace_back(lo, hi);
  }
  // Apart from each other: their bounding boxes do not overlap.
  for (std::size_t i = 0; i < bounds.size(); ++i)
    for (std::size_t j = i + 1; j < bounds.size(); ++j) {
      const bool overlap = glm::all(glm::lessThan(bounds[i].first, bounds[j].second)) &&
                           glm::all(glm::lessThan(bounds[j].first, bounds[i].second));
      EXPECT_FALSE(overlap) << kSpecularObjects[i] << " and " << kSpecularObjects[j];
    }
}

}  // namespace
}  // namespace gib::scene
