// Scene files' mirror and glass materials and OBJ normals (scene_file.h).
#include "scene/scene_file.h"

#include "scene/metals.h"
#include "scene/scene_file_fixture.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <string>

namespace gib::scene::test {
namespace {

// A camera, the materials given and one mesh of the first of them.
std::string sceneWith(const std::string& materials, const std::string& mesh = "file = \"quad.obj\"",
                      const std::string& material = "m") {
  return "[camera]\nposition = [0, 0, 5]\nlook_at = [0, 0, 0]\nvertical_fov_deg = 45\n" +
         materials + "\n[[meshes]]\n" + mesh + "\nmaterial = \"" + material + "\"\n";
}

TEST_F(SceneFileTest, MirrorOfANamedMetalOrOfItsIndex) {
  const Scene gold =
      loadSceneFile(write(sceneWith("[materials.m]\ntype = \"mirror\"\nmetal = \"gold\"")));
  const Material& g = gold.materials.at(0);
  EXPECT_EQ(g.type, MaterialType::kMirror);
  EXPECT_FALSE(g.perfect_mirror);
  EXPECT_EQ(g.conductor_n, findMetal("gold")->n);
  EXPECT_EQ(g.conductor_k, findMetal("gold")->k);
  EXPECT_EQ(g.name, "m");

  const Scene perfect =
      loadSceneFile(write(sceneWith("[materials.m]\ntype = \"mirror\"\nmetal = \"perfect\"")));
  EXPECT_TRUE(perfect.materials.at(0).perfect_mirror);

  const Scene own = loadSceneFile(
      write(sceneWith("[materials.m]\ntype = \"mirror\"\nn = [0.2, 0.9, 1.1]\nk = [3, 2.5, 0]")));
  EXPECT_EQ(own.materials.at(0).conductor_n, Rgb(0.2f, 0.9f, 1.1f));
  EXPECT_EQ(own.materials.at(0).conductor_k, Rgb(3.0f, 2.5f, 0.0f));
}

TEST_F(SceneFileTest, GlassWithItsIndexAndAbsorption) {
  const Scene plain = loadSceneFile(write(sceneWith("[materials.m]\ntype = \"glass\"")));
  EXPECT_EQ(plain.materials.at(0).type, MaterialType::kGlass);
  EXPECT_EQ(plain.materials.at(0).ior, 1.5f);
  EXPECT_EQ(plain.materials.at(0).absorption, Rgb(0.0f));
  const Scene tinted = loadSceneFile(
      write(sceneWith("[materials.m]\ntype = \"glass\"\nior = 1.33\nabsorption = [0.1, 0, 0.2]")));
  EXPECT_FLOAT_EQ(tinted.materials.at(0).ior, 1.33f);
  EXPECT_EQ(tinted.materials.at(0).absorption, Rgb(0.1f, 0.0f, 0.2f));
}

TEST_F(SceneFileTest, BadMirrorsAndGlassArePositionedErrors) {
  struct Case {
    std::string material, at, says;
  };
  const Case cases[] = {
      {"type = \"glass\"\nior = 0", "ior = 0", "materials.m.ior must be in [1, 4], got 0"},
      {"type = \"glass\"\nior = -1.5", "ior = -1.5", "must be in [1, 4]"},
      {"type = \"glass\"\nior = 4.5", "ior = 4.5", "must be in [1, 4]"},
      {"type = \"glass\"\nior = nan", "ior = nan", "materials.m.ior must be a finite number"},
      {"type = \"glass\"\nabsorption = [0, -1, 0]", "absorption", "must not be negative"},
      {"type = \"glass\"\ndiffuse = [0.5, 0.5, 0.5]", "diffuse",
       "unknown key 'diffuse' in [materials.m] (type \"glass\")"},
      {"type = \"mirror\"\nmetal = \"tin\"", "metal = \"tin\"",
       "'tin' is not a known metal; use one of perfect, aluminium, silver, gold, copper"},
      {"type = \"mirror\"\nn = [1, 1, 1]\nk = [3, -0.5, 3]", "k = [3, -0.5, 3]",
       "materials.m.k (kappa) must be >= 0"},
      {"type = \"mirror\"\nn = [1, 0, 1]\nk = [3, 3, 3]", "n = [1, 0, 1]",
       "materials.m.n must be > 0"},
      {"type = \"mirror\"\nn = [1, 1, 1]", "n = [1, 1, 1]", "gives n without k"},
      {"type = \"mirror\"\nmetal = \"gold\"\nk = [3, 3, 3]", "k = [3, 3, 3]",
       "gives both metal and n/k"},
      {"type = \"mirror\"", "[materials.m]", "gives neither metal nor n and k"},
      {"type = \"mirror\"\nmetal = \"gold\"\nemission = [1, 1, 1]", "emission",
       "unknown key 'emission'"},
      {"type = \"chrome\"", "type = \"chrome\"",
       "materials.m.type must be \"lambert\", \"phong\", \"mirror\" or \"glass\""},
  };
  for (const Case& c : cases) {
    const std::string text = sceneWith("[materials.m]\n" + c.material);
    EXPECT_THAT(expectErrorAt(text, c.at), HasSubstr(c.says)) << c.material;
  }
}

// A unit quad split in two triangles whose shared corners carry different normals (a crease), and
// an unshared corner normal of length 2.
constexpr const char* kCreasedObj = R"(v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vn 0 0 2
vn 0 0.6 0.8
vn 0.6 0 0.8
f 1//1 2//1 3//2
f 1//3 3//3 4//1
)";

TEST_F(SceneFileTest, ObjNormalsBecomeOneUnitNormalPerVertex) {
  writeFile(dir_ / "creased.obj", kCreasedObj);
  const Scene scene =
      loadSceneFile(write(sceneWith("[materials.m]\ntype = \"glass\"", "file = \"creased.obj\"")));
  const Mesh& mesh = scene.meshes.at(0);
  // Corners (position, normal): (1,1) (2,1) (3,2) (1,3) (3,3) (4,1): six distinct pairs, so the
  // two positions used with two normals each are split.
  ASSERT_EQ(mesh.triangles.size(), 2u);
  ASSERT_EQ(mesh.positions.size(), 6u);
  ASSERT_EQ(mesh.normals.size(), 6u);
  for (int c = 0; c < 3; ++c)
    for (const glm::uvec3& t : mesh.triangles)
      EXPECT_NEAR(glm::length(mesh.normals[t[c]]), 1.0f, 1e-6f);
  const glm::uvec3 first = mesh.triangles[0], second = mesh.triangles[1];
  EXPECT_EQ(mesh.positions[first[0]], mesh.positions[second[0]]);  // position 1, twice
  EXPECT_NE(first[0], second[0]);                                  // split: two normals
  EXPECT_EQ(mesh.normals[first[0]], glm::vec3(0, 0, 1));           // normalised
  EXPECT_EQ(mesh.normals[second[0]], glm::vec3(0.6f, 0, 0.8f));
  EXPECT_EQ(mesh.normals[first[2]], glm::vec3(0, 0.6f, 0.8f));
  EXPECT_EQ(mesh.positions[second[2]], glm::vec3(0, 1, 0));
  EXPECT_EQ(mesh.normals[second[2]], glm::vec3(0, 0, 1));
}

TEST_F(SceneFileTest, ObjNormalsFollowScaleAndFlipOrAreIgnored) {
  writeFile(dir_ / "creased.obj", kCreasedObj);
  const Scene scaled = loadSceneFile(
      write(sceneWith("[materials.m]\ntype = \"glass\"",
                      "file = \"creased.obj\"\nscale = [1, 2, 1]\nflip_normals = true")));
  const Mesh& mesh = scaled.meshes.at(0);
  // (0, 0.6, 0.8) under the inverse transpose of diag(1, 2, 1), normalised and turned around
  // with the front side: −(0, 0.3, 0.8)/|…|.
  const glm::vec3 expected = -glm::normalize(glm::vec3(0, 0.3f, 0.8f));
  bool found = false;
  for (const glm::vec3& n : mesh.normals) found |= glm::length(n - expected) < 1e-6f;
  EXPECT_TRUE(found);
  for (const glm::vec3& n : mesh.normals) EXPECT_LT(n.z, 0.0f) << "flipped with the winding";

  const Scene flat = loadSceneFile(write(
      sceneWith("[materials.m]\ntype = \"glass\"", "file = \"creased.obj\"\nsmooth = false")));
  EXPECT_TRUE(flat.meshes.at(0).normals.empty());
  EXPECT_EQ(flat.meshes.at(0).positions.size(), 4u) << "the OBJ's vertices as they are";
}

TEST_F(SceneFileTest, ObjWithoutNormalsStaysFlat) {
  const Scene scene = loadSceneFile(write(sceneWith("[materials.m]\ntype = \"glass\"")));
  EXPECT_TRUE(scene.meshes.at(0).normals.empty());
  EXPECT_EQ(scene.meshes.at(0).positions.size(), 4u);
}

TEST_F(SceneFileTest, BadObjNormalsNameTheFileAndTheProblem) {
  struct Case {
    const char* obj;
    const char* says;
  };
  const Case cases[] = {
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//1\n",
       "refers to normal 2 but has 1 normals (vn lines)"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 2 4 3\n",
       "gives some face corners a normal (vn) and others none, the first in triangle 2"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0\nf 1//1 2//1 3//1\n",
       "has a zero or non-finite normal at vn line 1"},
  };
  for (const Case& c : cases) {
    writeFile(dir_ / "bad.obj", c.obj);
    const std::string text = sceneWith("[materials.m]\ntype = \"glass\"", "file = \"bad.obj\"");
    const std::string message = expectErrorAt(text, "file = \"bad.obj\"");
    EXPECT_THAT(message, HasSubstr(c.says)) << c.obj;
    EXPECT_THAT(message, HasSubstr((dir_ / "bad.obj").string()));
  }
}

}  // namespace
}  // namespace gib::scene::test
