#include "scene/builtin_scenes.h"
#include "common/input_error.h"
#include "scene/camera.h"
#include "scene/metals.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

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

// The hashes of the built-in scenes' defaults before mirrors and glass existed (computed with the
// build of that time): stored references are keyed by them, so new parameters must keep them.
constexpr const char* kCornellHash = "f35cc26e1cfcf433408ddbea59855255";
constexpr const char* kEmptyCornellHash = "c7b34a69654d0d5901953bf772499e70";
constexpr const char* kFurnaceHash = "2697d276bf8995647466d825b8bc59e5";

TEST(CornellBox, DefaultsKeepTheHashesStoredReferencesHave) {
  EXPECT_EQ(hashScene(loadScene("cornell")), kCornellHash);
  EXPECT_EQ(hashScene(loadScene("cornell", {"blocks=false"})), kEmptyCornellHash);
  EXPECT_EQ(hashScene(loadScene("cornell", {"spheres=none", "metal=silver", "ior=1.5",
                                            "absorption=0,0,0", "light=area"})),
            kCornellHash);
  EXPECT_EQ(hashScene(loadScene("furnace")), kFurnaceHash);
  EXPECT_EQ(hashScene(loadScene("furnace", {"object=none"})), kFurnaceHash);
}

const Mesh* findMesh(const Scene& scene, const std::string& name) {
  for (const Mesh& mesh : scene.meshes)
    if (mesh.name == name) return &mesh;
  return nullptr;
}

// The sphere's centre and radius from its vertices' bounding box.
std::pair<glm::vec3, float> sphereOf(const Mesh& mesh) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::vec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return {0.5f * (lo + hi), 0.5f * (hi.y - lo.y)};
}

TEST(CornellBox, SpheresReplaceTheBlocksWithSmoothMirrorAndGlass) {
  const Scene s = loadScene("cornell", {"spheres=mirror_glass"});
  EXPECT_EQ(findMesh(s, "short_block"), nullptr);
  EXPECT_EQ(findMesh(s, "tall_block"), nullptr);
  const Mesh* mirror = findMesh(s, "mirror_sphere");
  const Mesh* glass = findMesh(s, "glass_sphere");
  ASSERT_NE(mirror, nullptr);
  ASSERT_NE(glass, nullptr);
  EXPECT_TRUE(s.hasIdealSpecular());
  // Silver by default, glass of index 1.5 without absorption.
  const Material& m = s.materials.at(mirror->material);
  EXPECT_EQ(m.type, MaterialType::kMirror);
  EXPECT_FALSE(m.perfect_mirror);
  EXPECT_EQ(m.conductor_n, findMetal("silver")->n);
  EXPECT_EQ(m.conductor_k, findMetal("silver")->k);
  const Material& g = s.materials.at(glass->material);
  EXPECT_EQ(g.type, MaterialType::kGlass);
  EXPECT_EQ(g.ior, 1.5f);
  EXPECT_EQ(g.absorption, Rgb(0.0f));
  int specular_meshes = 0;
  for (const Mesh& mesh : s.meshes) {
    const bool specular = isIdealSpecular(s.materials.at(mesh.material).type);
    specular_meshes += specular;
    EXPECT_EQ(mesh.normals.empty(), !specular) << mesh.name << ": only the spheres are smooth";
  }
  EXPECT_EQ(specular_meshes, 2);
  // 64 rings × 128 segments: two poles and 63 rings of vertices.
  EXPECT_EQ(mirror->positions.size(), 2u + 63u * 128u);
  EXPECT_EQ(mirror->normals.size(), mirror->positions.size());
  // Blocks or not, the spheres take their place: the same scene.
  EXPECT_EQ(hashScene(s),
            hashScene(loadScene("cornell", {"spheres=mirror_glass", "blocks=false"})));
}

TEST(CornellBox, SpheresStandOnTheFloorInViewAndClearOfTheWalls) {
  const Scene s = loadScene("cornell", {"spheres=mirror_glass"});
  const CameraFrame frame = makeCameraFrame(s.camera, 512, 512);
  for (const char* name : {"mirror_sphere", "glass_sphere"}) {
    const Mesh& mesh = *findMesh(s, name);
    const auto [centre, radius] = sphereOf(mesh);
    EXPECT_NEAR(radius, 100.0f, 1e-3f) << name;
    EXPECT_NEAR(centre.y - radius, 0.0f, 1e-3f) << name << " stands on the floor";
    // The walls lean by at most 3.2 mm over the box's depth; 50 mm clear of the planes x = 0,
    // x = 552.8 − 3.2, z = 0 (the opening) and z = 559.2 is clear of every wall.
    EXPECT_GT(centre.x - radius, 50.0f) << name;
    EXPECT_LT(centre.x + radius, 549.6f - 50.0f) << name;
    EXPECT_GT(centre.z - radius, 50.0f) << name;
    EXPECT_LT(centre.z + radius, 559.2f - 50.0f) << name;
    // Every vertex projects inside the image.
    for (const glm::vec3& p : mesh.positions) {
      const glm::vec3 d = p - frame.origin;
      const float depth = glm::dot(d, frame.forward);
      ASSERT_GT(depth, 0.0f);
      EXPECT_LT(std::abs(glm::dot(d, frame.right)) / depth, frame.tan_half_fov_y * frame.aspect);
      EXPECT_LT(std::abs(glm::dot(d, frame.up)) / depth, frame.tan_half_fov_y);
    }
  }
  const float apart = glm::length(sphereOf(*findMesh(s, "mirror_sphere")).first -
                                  sphereOf(*findMesh(s, "glass_sphere")).first);
  EXPECT_GT(apart, 200.0f) << "the spheres do not touch";
}

TEST(CornellBox, SphereParametersReachTheMaterials) {
  const Scene gold = loadScene("cornell", {"spheres=mirror", "metal=gold"});
  EXPECT_EQ(findMesh(gold, "glass_sphere"), nullptr);
  const Material& m = gold.materials.at(findMesh(gold, "mirror_sphere")->material);
  EXPECT_EQ(m.conductor_n, findMetal("gold")->n);
  const Scene perfect = loadScene("cornell", {"spheres=mirror", "metal=perfect"});
  EXPECT_TRUE(perfect.materials.at(findMesh(perfect, "mirror_sphere")->material).perfect_mirror);
  EXPECT_NE(hashScene(gold), hashScene(perfect));

  const Scene glass =
      loadScene("cornell", {"spheres=glass", "ior=1.33", "absorption=0.01,0,0.002"});
  EXPECT_EQ(findMesh(glass, "mirror_sphere"), nullptr);
  const Material& g = glass.materials.at(findMesh(glass, "glass_sphere")->material);
  EXPECT_FLOAT_EQ(g.ior, 1.33f);
  EXPECT_EQ(g.absorption, Rgb(0.01f, 0.0f, 0.002f));
  EXPECT_NE(hashScene(glass), hashScene(loadScene("cornell", {"spheres=glass"})));
}

TEST(CornellBox, MirrorCentreMovesTheMirrorSphere) {
  // The default is the classic position: the same scene, the same hash.
  const Scene classic = loadScene("cornell", {"spheres=mirror_glass"});
  EXPECT_EQ(hashScene(classic),
            hashScene(loadScene("cornell", {"spheres=mirror_glass", "mirror_centre=380,100,380"})));
  EXPECT_EQ(sphereOf(*findMesh(classic, "mirror_sphere")).first, glm::vec3(380, 100, 380));
  // Near the red wall and the back wall, as in Fig. 6.6, and at the corners of the allowed range.
  for (const char* centre : {"449,100,459", "100,448,100", "449,300,200"}) {
    const Scene moved =
        loadScene("cornell", {"spheres=mirror_glass", std::string("mirror_centre=") + centre});
    const Mesh& mirror = *findMesh(moved, "mirror_sphere");
    const auto [c, radius] = sphereOf(mirror);
    EXPECT_NE(hashScene(moved), hashScene(classic)) << centre;
    EXPECT_NEAR(radius, 100.0f, 1e-3f) << centre;
    // Inside the box: the left wall leans in to x = 549.6 at the floor's back, the light hangs at
    // y = 548.7.
    EXPECT_GE(c.y - radius, -1e-3f) << centre;
    EXPECT_LE(c.y + radius, 548.7f) << centre;
    EXPECT_GE(c.x - radius, 0.0f) << centre;
    EXPECT_LE(c.x + radius, 549.6f) << centre;
    EXPECT_GE(c.z - radius, 0.0f) << centre;
    EXPECT_LE(c.z + radius, 559.2f) << centre;
    // The glass sphere stays where it was.
    EXPECT_EQ(findMesh(moved, "glass_sphere")->positions,
              findMesh(classic, "glass_sphere")->positions);
  }
  // Without a mirror sphere the parameter changes nothing.
  EXPECT_EQ(hashScene(loadScene("cornell", {"spheres=glass", "mirror_centre=200,200,200"})),
            hashScene(loadScene("cornell", {"spheres=glass"})));
}

TEST(CornellBox, MirrorCentreOutsideTheBoxIsAnInputError) {
  for (const char* centre : {"380,99,380", "380,50,380", "450,100,380", "380,449,380",
                             "380,100,460", "99,100,380", "380,100,-100", "380,100", "nan,100,380"})
    EXPECT_THROW(loadScene("cornell", {"spheres=mirror", std::string("mirror_centre=") + centre}),
                 InputError)
        << centre;
  // Into the glass sphere (centre (185, 100, 170)), with both spheres only.
  EXPECT_THROW(loadScene("cornell", {"spheres=mirror_glass", "mirror_centre=250,100,250"}),
               InputError);
  EXPECT_NO_THROW(loadScene("cornell", {"spheres=mirror", "mirror_centre=250,100,250"}));
  try {
    loadScene("cornell", {"spheres=mirror", "mirror_centre=450,100,380"});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("give x in [100, 449]"), std::string::npos) << e.what();
  }
}

TEST(CornellBox, BadSphereParametersAreInputErrors) {
  for (const std::vector<std::string>& bad :
       std::vector<std::vector<std::string>>{{"ior=0"},
                                             {"ior=0.9"},
                                             {"ior=4.5"},
                                             {"ior=nan"},
                                             {"absorption=-1,0,0"},
                                             {"metal=tin"},
                                             {"spheres=three"},
                                             {"light=point"}})
    EXPECT_THROW(loadScene("cornell", bad), InputError) << bad[0];
}

TEST(CornellBox, SpotLightReplacesTheAreaLightWithTheSamePower) {
  const Scene area = loadScene("cornell");
  const Scene spot = loadScene("cornell", {"light=spot"});
  EXPECT_FALSE(spot.hasEmissiveTriangles());
  EXPECT_EQ(findMesh(spot, "light"), nullptr);
  ASSERT_EQ(spot.spot_lights.size(), 1u);
  const SpotLight& l = spot.spot_lights[0];
  EXPECT_EQ(l.direction, glm::vec3(0, -1, 0));
  EXPECT_NEAR(l.position.x, 278.0f, 1e-3f);
  EXPECT_NEAR(l.position.z, 279.5f, 1e-3f);
  EXPECT_LT(l.position.y, 548.8f);
  EXPECT_GT(l.position.y, 540.0f);
  // A Lambertian light of radiance L and area A emits π·L·A; the spot, I0·cos θ over the lower
  // hemisphere, 2π·I0/(n + 1) = π·I0 with n = 1.
  const Rgb radiance = area.materials.at(findMesh(area, "light")->material).emission;
  EXPECT_EQ(l.cone_angle_deg, 90.0f);
  EXPECT_EQ(l.falloff_exponent, 1.0f);
  const float pi = glm::pi<float>();
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(2.0f * pi * l.intensity[c] / (l.falloff_exponent + 1.0f),
                pi * radiance[c] * 130.0f * 105.0f, 1e-3f * pi * radiance[c] * 130.0f * 105.0f);
  // The rest of the box is unchanged, and spheres combine with it.
  const Scene both = loadScene("cornell", {"light=spot", "spheres=glass"});
  EXPECT_EQ(both.spot_lights.size(), 1u);
  EXPECT_NE(findMesh(both, "glass_sphere"), nullptr);
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

TEST(Furnace, ObjectsAreALosslessSmoothSphereInView) {
  const Scene none = loadScene("furnace");
  EXPECT_EQ(none.meshes.size(), 1u);
  EXPECT_TRUE(none.meshes[0].normals.empty()) << "the walls stay flat";
  for (const char* object : {"mirror", "glass"}) {
    const Scene s = loadScene("furnace", {std::string("object=") + object});
    ASSERT_EQ(s.meshes.size(), 2u) << object;
    const Mesh& sphere = s.meshes[1];
    const Material& m = s.materials.at(sphere.material);
    if (std::string(object) == "mirror") {
      EXPECT_EQ(m.type, MaterialType::kMirror);
      EXPECT_TRUE(m.perfect_mirror) << "a perfect mirror keeps every pixel at 1";
    } else {
      EXPECT_EQ(m.type, MaterialType::kGlass);
      EXPECT_EQ(m.ior, 1.5f);
      EXPECT_EQ(m.absorption, Rgb(0.0f)) << "lossless glass keeps every pixel at 1";
    }
    EXPECT_EQ(m.emission, Rgb(0.0f));
    ASSERT_EQ(sphere.normals.size(), sphere.positions.size());
    // Outward normals (the glass's front side is its outside), in front of the camera.
    const auto [centre, radius] = sphereOf(sphere);
    EXPECT_NEAR(radius, 0.25f, 1e-5f);
    EXPECT_LT(centre.z + radius, 0.0f);
    for (std::size_t i = 0; i < sphere.positions.size(); ++i)
      EXPECT_GT(glm::dot(sphere.normals[i], sphere.positions[i] - centre), 0.0f);
    EXPECT_EQ(s.meshes[0].positions, none.meshes[0].positions);
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
