#include "common/input_error.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"
#include "support/mesh_topology.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace gib::scene {
namespace {

// The room's interior (metres, scene/room.cpp): x and z in [−2, 2], y in [0, 4].
constexpr float kHalfWidth = 2.0f, kHeight = 4.0f;
constexpr float kObjectRadius = 0.5f;
constexpr const char* kWalls[] = {"floor",      "ceiling",   "red_wall",
                                  "green_wall", "blue_wall", "yellow_wall"};

const Mesh& meshNamed(const Scene& scene, const std::string& name) {
  for (const Mesh& mesh : scene.meshes)
    if (mesh.name == name) return mesh;
  throw std::runtime_error("the room has no mesh '" + name + "'");
}

glm::vec3 boundsCentre(const Mesh& mesh) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::vec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return 0.5f * (lo + hi);
}

TEST(Room, IsABuiltinSceneWithADescription) {
  bool found = false;
  for (const BuiltinSceneInfo& info : builtinScenes())
    if (info.name == "room") {
      found = true;
      EXPECT_NE(info.description.find("Figs. 7.10-7.13"), std::string::npos);
    }
  EXPECT_TRUE(found);
  const Scene scene = loadScene("room");
  EXPECT_EQ(scene.name, "room");
  EXPECT_EQ(scene.default_width, 512);
  EXPECT_EQ(scene.default_height, 512);
  EXPECT_EQ(
      hashScene(scene),
      hashScene(loadScene("room", {"object=diffuse", "shape=sphere", "object_position=0,1.5,0"})));
  // Light: a few thousand triangles, for the techniques that treat each one.
  EXPECT_LT(scene.triangleCount(), 6000u);
}

TEST(Room, IsClosedAndFacesInwards) {
  // Light cannot escape: the six walls meet at their edges, every edge between two triangles,
  // and enclose the room with their front sides inside (negative volume: they face inwards).
  const Scene scene = loadScene("room");
  std::vector<const Mesh*> walls;
  for (const char* name : kWalls) walls.push_back(&meshNamed(scene, name));
  EXPECT_EQ(test::unmatchedEdges(walls), 0u);
  EXPECT_NEAR(test::signedVolume(walls), -(2.0 * kHalfWidth) * (2.0 * kHalfWidth) * kHeight, 1e-4);
  // Distinct diffuse colours that lose energy at every bounce.
  for (const char* name : kWalls) {
    const Material& m = scene.materials.at(meshNamed(scene, name).material);
    EXPECT_EQ(m.type, MaterialType::kLambert) << name;
    EXPECT_LE(std::max({m.diffuse.r, m.diffuse.g, m.diffuse.b}), 0.8f) << name;
    EXPECT_FALSE(m.isEmissive()) << name;
  }
  EXPECT_NE(scene.materials.at(meshNamed(scene, "red_wall").material).diffuse,
            scene.materials.at(meshNamed(scene, "green_wall").material).diffuse);
}

TEST(Room, FireBallsAreTheOnlyLights) {
  const Scene scene = loadScene("room");
  EXPECT_TRUE(scene.spot_lights.empty());
  EXPECT_TRUE(scene.directional_lights.empty());
  EXPECT_EQ(scene.sky_radiance, Rgb(0.0f));
  EXPECT_TRUE(scene.medium.empty());
  EXPECT_TRUE(scene.hasEmissiveTriangles());
  int balls = 0;
  for (const Mesh& mesh : scene.meshes) {
    if (!scene.materials.at(mesh.material).isEmissive()) continue;
    ++balls;
    EXPECT_EQ(mesh.name.rfind("fire_ball_", 0), 0u) << mesh.name;
    // A small closed sphere facing outwards (emission leaves the front side), away from the walls.
    EXPECT_EQ(test::unmatchedEdges({&mesh}), 0u) << mesh.name;
    EXPECT_GT(test::signedVolume({&mesh}), 0.0) << mesh.name;
    const glm::vec3 c = boundsCentre(mesh);
    for (const glm::vec3& p : mesh.positions) {
      const float r = glm::length(p - c);
      EXPECT_GT(r, 0.14f) << mesh.name;
      EXPECT_LT(r, 0.21f) << mesh.name;
    }
    EXPECT_GT(kHalfWidth - std::abs(c.x), 0.5f) << mesh.name;
    EXPECT_GT(kHalfWidth - std::abs(c.z), 0.5f) << mesh.name;
    EXPECT_GT(c.y, 0.5f) << mesh.name;
    EXPECT_LT(c.y, kHeight - 0.5f) << mesh.name;
    // Warm: more red than green than blue.
    const Rgb e = scene.materials.at(mesh.material).emission;
    EXPECT_GT(e.r, e.g);
    EXPECT_GT(e.g, e.b);
  }
  EXPECT_GE(balls, 3);
  EXPECT_LE(balls, 4);
}

TEST(Room, ObjectIsTheLastMeshWithTheMaterialAsked) {
  for (const char* shape : {"sphere", "torus"})
    for (const char* object : {"diffuse", "glossy"}) {
      const Scene scene =
          loadScene("room", {std::string("shape=") + shape, std::string("object=") + object});
      const Mesh& last = scene.meshes.back();
      EXPECT_EQ(last.name, std::string("object_") + shape);
      ASSERT_EQ(last.normals.size(), last.positions.size()) << "smooth-shaded";
      EXPECT_EQ(test::unmatchedEdges({&last}), 0u) << shape;
      EXPECT_GT(test::signedVolume({&last}), 0.0) << shape;
      const Material& m = scene.materials.at(last.material);
      EXPECT_FALSE(m.isEmissive());
      if (std::string(object) == "diffuse") {
        EXPECT_EQ(m.type, MaterialType::kLambert);
        EXPECT_EQ(m.diffuse, Rgb(0.7f));
      } else {
        // The book's glossy objects have shininess 5 (Figs. 7.12, 7.13).
        EXPECT_EQ(m.type, MaterialType::kPhong);
        EXPECT_EQ(m.exponent, 5.0f);
        EXPECT_GT(m.specular.g, 0.0f);
        EXPECT_LE(m.diffuse.g + m.specular.g, 1.0f);
      }
      // Within 0.5 m of the default position, the room's middle.
      for (const glm::vec3& p : last.positions)
        EXPECT_LE(glm::length(p - glm::vec3(0.0f, 1.5f, 0.0f)), kObjectRadius + 1e-5f) << shape;
    }
}

TEST(Room, CameraFramesTheObjectFromInside) {
  const Scene scene = loadScene("room");
  const glm::vec3 cam = scene.camera.position;
  EXPECT_LT(std::abs(cam.x), kHalfWidth);
  EXPECT_LT(std::abs(cam.z), kHalfWidth);
  EXPECT_GT(cam.y, 0.0f);
  EXPECT_LT(cam.y, kHeight);
  const CameraFrame f = makeCameraFrame(scene.camera, scene.default_width, scene.default_height);
  for (const glm::vec3& p : scene.meshes.back().positions) {
    const glm::vec3 v = p - f.origin;
    const float depth = glm::dot(v, f.forward);
    ASSERT_GT(depth, 0.0f);
    EXPECT_LT(std::abs(glm::dot(v, f.right) / depth), f.tan_half_fov_y * f.aspect);
    EXPECT_LT(std::abs(glm::dot(v, f.up) / depth), f.tan_half_fov_y);
  }
  // The red wall (x = −2) on the image's left.
  EXPECT_GT(f.right.x, 0.9f);
}

TEST(Room, ObjectPositionMovesTheObjectAndChangesTheHash) {
  const Scene centre = loadScene("room");
  const Scene moved = loadScene("room", {"object_position=1.2,0.55,-1.4"});
  EXPECT_NE(hashScene(moved), hashScene(centre));
  const glm::vec3 c = boundsCentre(moved.meshes.back());
  EXPECT_NEAR(c.x, 1.2f, 1e-4f);
  EXPECT_NEAR(c.y, 0.55f, 1e-4f);
  EXPECT_NEAR(c.z, -1.4f, 1e-4f);
  // Only the object moved.
  ASSERT_EQ(moved.meshes.size(), centre.meshes.size());
  for (std::size_t i = 0; i + 1 < moved.meshes.size(); ++i)
    EXPECT_EQ(moved.meshes[i].positions, centre.meshes[i].positions) << moved.meshes[i].name;
  // Still inside the room.
  for (const glm::vec3& p : moved.meshes.back().positions) {
    EXPECT_LT(std::abs(p.x), kHalfWidth);
    EXPECT_GT(p.y, 0.0f);
    EXPECT_LT(std::abs(p.z), kHalfWidth);
  }
  const Scene torus = loadScene("room", {"shape=torus", "object_position=-1.45,3.45,1.0"});
  EXPECT_NEAR(boundsCentre(torus.meshes.back()).x, -1.45f, 0.01f);
}

TEST(Room, BadValuesAreInputErrors) {
  for (const char* bad :
       {"object=mirror", "shape=bunny", "object_position=0,0,0", "object_position=1.5,1.5,0",
        "object_position=0,3.5,0", "object_position=0,1.5,-1.5", "object_position=0,1.5",
        "object_position=nan,1.5,0", "object_position=-1.3,3.0,-1.2" /* a fire ball */,
        "object_position=0,2,1.45" /* around the camera */, "bogus=1"})
    EXPECT_THROW(loadScene("room", {bad}), InputError) << bad;
  try {
    loadScene("room", {"object_position=0,0.2,0"});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("y in [0.55, 3.45]"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace gib::scene
