#include "scene/builtin_scenes.h"
#include "common/input_error.h"
#include "scene/camera.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <map>
#include <utility>

namespace gib::scene {
namespace {

TEST(CornellBox, HasThePublishedGeometryAndCamera) {
  const Scene s = loadScene("cornell");
  // Five walls, the light and two blocks of five quads each: 16 quads.
  EXPECT_EQ(s.triangleCount(), 32u);
  EXPECT_NEAR(s.camera.vertical_fov_deg, 39.3077f, 1e-3f);
  EXPECT_EQ(s.camera.position, glm::vec3(278, 273, -800));
  // The light is 130 × 105 mm, emits downwards, and is the only emitter.
  float light_area = 0;
  for (const Mesh& m : s.meshes) {
    if (!s.materials[m.material].isEmissive()) continue;
    for (const glm::uvec3& t : m.triangles) {
      glm::vec3 n =
          glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
      light_area += 0.5f * glm::length(n);
      EXPECT_LT(n.y, 0) << "the light must face down";
    }
  }
  EXPECT_NEAR(light_area, 130.0f * 105.0f, 1e-2f);
}

TEST(CornellBox, BlocksCanBeLeftOutWithoutChangingTheDefaultScene) {
  const Scene with = loadScene("cornell");
  const Scene without = loadScene("cornell", {"blocks=false"});
  EXPECT_EQ(with.triangleCount(), 32u);
  EXPECT_EQ(without.triangleCount(), 12u);  // five walls and the light
  // The default is the published box: its hash, which keys stored references, is unchanged.
  EXPECT_EQ(hashScene(with), hashScene(loadScene("cornell", {"blocks=true"})));
  EXPECT_NE(hashScene(with), hashScene(without));
  EXPECT_THROW(loadScene("cornell", {"blocks=no"}), InputError);
}

TEST(CornellBox, RedWallIsOnTheLeftOfTheImage) {
  // Right-handed world, camera looking +z: +x is image left, where the published red wall is.
  const Scene s = loadScene("cornell");
  CameraFrame f = makeCameraFrame(s.camera, 512, 512);
  EXPECT_NEAR(f.right.x, -1.0f, 1e-6f);
  glm::vec3 left = cameraRayDirection(f, 512, 512, 0.5f, 256);
  EXPECT_GT(left.x, 0);
}

TEST(Camera, PixelCentresAreAtHalfIntegers) {
  Camera c;
  c.position = {0, 0, 0};
  c.look_at = {0, 0, -1};
  c.vertical_fov_deg = 90;
  CameraFrame f = makeCameraFrame(c, 4, 2);
  // The image centre looks straight ahead; the top-left corner at (−aspect, +1)·tan(45°).
  glm::vec3 centre = cameraRayDirection(f, 4, 2, 2.0f, 1.0f);
  EXPECT_NEAR(centre.z, -1.0f, 1e-6f);
  glm::vec3 corner = cameraRayDirection(f, 4, 2, 0.0f, 0.0f);
  EXPECT_NEAR(corner.x / -corner.z, -2.0f, 1e-5f);
  EXPECT_NEAR(corner.y / -corner.z, 1.0f, 1e-5f);
}

TEST(Furnace, SphereIsClosed) {
  // Every edge is shared by exactly two triangles, with opposite orientations.
  const Scene s = loadScene("furnace");
  std::map<std::pair<unsigned, unsigned>, int> directed;
  for (const glm::uvec3& t : s.meshes.at(0).triangles)
    for (int k = 0; k < 3; ++k) directed[{t[k], t[(k + 1) % 3]}]++;
  for (auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(directed.count({edge.second, edge.first}), 1u);
  }
}

TEST(SceneHash, IsStableAndSeesEveryChange) {
  const Scene a = loadScene("cornell");
  EXPECT_EQ(hashScene(a), hashScene(loadScene("cornell")));
  EXPECT_EQ(hashScene(a).size(), 32u);
  Scene b = a;
  b.meshes[0].positions[0].x += 0.001f;
  EXPECT_NE(hashScene(a), hashScene(b));
  Scene c = a;
  c.materials[0].diffuse.g *= 0.99f;
  EXPECT_NE(hashScene(a), hashScene(c));
  Scene d = a;
  d.camera.vertical_fov_deg += 1;
  EXPECT_NE(hashScene(a), hashScene(d));
  Scene e = a;
  e.name = "renamed";
  e.provenance = "elsewhere";
  EXPECT_EQ(hashScene(a), hashScene(e)) << "names do not change the image";
  EXPECT_NE(hashScene(a), hashScene(loadScene("furnace")));
}

TEST(LoadScene, UnknownNameListsTheBuiltinScenes) {
  try {
    loadScene("cornel");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cornell"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("furnace"), std::string::npos);
  }
}

TEST(ValidateScene, RejectsEnergyGainAndBadIndices) {
  Scene s = loadScene("cornell");
  s.materials[0].diffuse = Rgb(0.9f);
  s.materials[0].type = MaterialType::kPhong;
  s.materials[0].specular = Rgb(0.2f);
  EXPECT_THROW(validateScene(s), InputError);
  Scene t = loadScene("cornell");
  t.meshes[0].triangles[0][0] = 999;
  EXPECT_THROW(validateScene(t), InputError);
}

}  // namespace
}  // namespace gib::scene
