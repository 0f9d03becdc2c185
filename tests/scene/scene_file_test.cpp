#include "scene/scene_file.h"

#include "scene/scene_file_fixture.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <string>

namespace gib::scene::test {
namespace {

TEST_F(SceneFileTest, LoadsAValidScene) {
  const Scene scene = loadSceneFile(write(kScene));
  EXPECT_EQ(scene.name, "test_room");
  EXPECT_THAT(scene.provenance, HasSubstr("scene file /"));
  EXPECT_THAT(scene.provenance, HasSubstr("scene.toml"));
  EXPECT_EQ(scene.camera.position, glm::vec3(278, 273, -800));
  EXPECT_EQ(scene.camera.look_at, glm::vec3(278, 273, 0));
  EXPECT_EQ(scene.camera.up, glm::vec3(0, 1, 0));
  EXPECT_FLOAT_EQ(scene.camera.vertical_fov_deg, 39.3077f);
  EXPECT_EQ(scene.default_width, 320);
  EXPECT_EQ(scene.default_height, 240);

  // Materials keep the order of the file.
  ASSERT_EQ(scene.materials.size(), 3u);
  EXPECT_EQ(scene.materials[0].name, "white");
  EXPECT_EQ(scene.materials[1].name, "gloss");
  EXPECT_EQ(scene.materials[1].type, MaterialType::kPhong);
  EXPECT_EQ(scene.materials[1].specular, Rgb(0.4f));
  EXPECT_FLOAT_EQ(scene.materials[1].exponent, 50.0f);
  EXPECT_EQ(scene.materials[2].name, "lamp");
  EXPECT_EQ(scene.materials[2].type, MaterialType::kLambert);
  EXPECT_EQ(scene.materials[2].emission, Rgb(17, 12, 4));

  ASSERT_EQ(scene.meshes.size(), 2u);
  EXPECT_EQ(scene.meshes[0].material, 2u);
  EXPECT_EQ(scene.meshes[0].triangles.size(), 2u);
  EXPECT_EQ(scene.meshes[1].material, 1u);
  EXPECT_EQ(scene.meshes[1].triangles.size(), 12u);
  EXPECT_EQ(scene.triangleCount(), 14u);
  EXPECT_TRUE(scene.hasEmissiveTriangles());
  // Scaled, then translated: (1, 1, 1) → (1·2 + 10, 1·3 + 20, 1·4 + 30).
  EXPECT_EQ(scene.meshes[1].positions[6], glm::vec3(12, 23, 34));
  EXPECT_EQ(scene.meshes[1].positions[0], glm::vec3(10, 20, 30));

  ASSERT_EQ(scene.spot_lights.size(), 1u);
  EXPECT_EQ(scene.spot_lights[0].direction, glm::vec3(0, -1, 0));
  EXPECT_EQ(scene.spot_lights[0].intensity, Rgb(100, 90, 80));
  EXPECT_FLOAT_EQ(scene.spot_lights[0].cone_angle_deg, 30.0f);
  EXPECT_FLOAT_EQ(scene.spot_lights[0].falloff_exponent, 2.0f);
  ASSERT_EQ(scene.directional_lights.size(), 1u);
  EXPECT_EQ(scene.directional_lights[0].direction, glm::vec3(0, 0, -1));
  EXPECT_EQ(scene.directional_lights[0].irradiance, Rgb(1, 2, 3));
  EXPECT_EQ(scene.sky_radiance, Rgb(0.1f, 0.2f, 0.3f));
}

TEST_F(SceneFileTest, DefaultsApply) {
  const std::string minimal = R"([camera]
position = [0, 0, 5]
look_at = [0, 0, 0]
vertical_fov_deg = 45
[materials.grey]
type = "lambert"
diffuse = [0.5, 0.5, 0.5]
[[meshes]]
file = "quad.obj"
material = "grey"
scale = 3
)";
  const Scene scene = loadSceneFile(write(minimal));
  EXPECT_EQ(scene.name, "scene");  // the file's stem
  EXPECT_EQ(scene.default_width, 512);
  EXPECT_EQ(scene.default_height, 512);
  EXPECT_EQ(scene.sky_radiance, Rgb(0.0f));
  EXPECT_EQ(scene.materials[0].emission, Rgb(0.0f));
  EXPECT_EQ(scene.meshes[0].positions[2], glm::vec3(3, 3, 0));  // uniform scale
  EXPECT_TRUE(scene.spot_lights.empty());
  EXPECT_TRUE(scene.directional_lights.empty());
}

glm::vec3 normalOf(const Mesh& mesh, std::size_t i) {
  const glm::uvec3 t = mesh.triangles[i];
  return glm::cross(mesh.positions[t.y] - mesh.positions[t.x],
                    mesh.positions[t.z] - mesh.positions[t.x]);
}

TEST_F(SceneFileTest, FlipNormalsReversesTheWinding) {
  const Scene plain = loadSceneFile(write(kScene));
  const Scene flipped = loadSceneFile(write(
      replaced(kScene, "material = \"lamp\"\n", "material = \"lamp\"\nflip_normals = true\n")));
  const Mesh& before = plain.meshes[0];
  const Mesh& after = flipped.meshes[0];
  ASSERT_EQ(before.triangles.size(), after.triangles.size());
  for (std::size_t i = 0; i < before.triangles.size(); ++i) {
    EXPECT_GT(normalOf(before, i).z, 0.0f);  // the OBJ's counter-clockwise quad faces +z
    EXPECT_LT(normalOf(after, i).z, 0.0f);
  }
}

// [camera] lens_radius and focus_distance: the thin lens (default: the pinhole, focused at
// look_at's distance); a negative radius or a focus distance <= 0 is refused where it is written.
TEST_F(SceneFileTest, CameraLens) {
  EXPECT_EQ(loadSceneFile(write(kScene)).camera.lens_radius, 0.0f);
  const std::string lens = replaced(kScene, "vertical_fov_deg = 39.3077",
                                    "vertical_fov_deg = 39.3077\nlens_radius = 20.0\n"
                                    "focus_distance = 1000.0");
  const Scene scene = loadSceneFile(write(lens));
  EXPECT_EQ(scene.camera.lens_radius, 20.0f);
  EXPECT_EQ(scene.camera.focus_distance, 1000.0f);
  EXPECT_THAT(expectErrorAt(replaced(kScene, "vertical_fov_deg = 39.3077",
                                     "vertical_fov_deg = 39.3077\nlens_radius = -1.0"),
                            "lens_radius = -1.0"),
              HasSubstr("camera.lens_radius -1 is not a lens radius"));
  EXPECT_THAT(expectErrorAt(replaced(kScene, "vertical_fov_deg = 39.3077",
                                     "vertical_fov_deg = 39.3077\nfocus_distance = -3.0"),
                            "focus_distance = -3.0"),
              HasSubstr("camera.focus_distance -3 is not a distance"));
}

TEST_F(SceneFileTest, TomlSyntaxErrorGivesItsPosition) {
  const std::string text = replaced(kScene, "height = 240", "height = = 240");
  const std::string message = expectErrorAt(text, "height = = 240");
  EXPECT_THAT(message, HasSubstr("invalid TOML"));
}

TEST_F(SceneFileTest, WrongTypeIsNamed) {
  const std::string text =
      replaced(kScene, "position = [278.0, 273.0, -800.0]", "position = [278.0, 273.0]");
  const std::string message = expectErrorAt(text, "position = [278.0, 273.0]");
  EXPECT_THAT(message, HasSubstr("camera.position must be an array of 3 numbers"));
}

TEST_F(SceneFileTest, StringWhereANumberIsExpected) {
  const std::string text = replaced(kScene, "exponent = 50.0", "exponent = \"50\"");
  const std::string message = expectErrorAt(text, "exponent = \"50\"");
  EXPECT_THAT(message, HasSubstr("materials.gloss.exponent must be a finite number"));
}

TEST_F(SceneFileTest, UnknownMaterialListsTheDefinedOnes) {
  const std::string text = replaced(kScene, "material = \"gloss\"", "material = \"glos\"");
  const std::string message = expectErrorAt(text, "material = \"glos\"");
  EXPECT_THAT(message, HasSubstr("meshes[1].material 'glos' is not defined"));
  EXPECT_THAT(message, HasSubstr("defined materials: gloss, lamp, white"));
}

TEST_F(SceneFileTest, UnknownKeyListsTheAllowedKeys) {
  const std::string text = replaced(kScene, "vertical_fov_deg = 39.3077", "vertical_fov = 39.3077");
  const std::string message = expectErrorAt(text, "vertical_fov = 39.3077");
  EXPECT_THAT(message, HasSubstr("unknown key 'vertical_fov' in [camera]"));
  EXPECT_THAT(message, HasSubstr("allowed keys: position, look_at, up, vertical_fov_deg"));
}

TEST_F(SceneFileTest, UnknownTopLevelTable) {
  const std::string text = replaced(kScene, "[sky]", "[skye]");
  const std::string message = expectErrorAt(text, "[skye]");
  EXPECT_THAT(message, HasSubstr("unknown key 'skye'"));
  EXPECT_THAT(message, HasSubstr("sky"));
}

TEST_F(SceneFileTest, PhongKeyOnALambertMaterialIsUnknown) {
  const std::string text =
      replaced(kScene, "diffuse = [0.7, 0.7, 0.7]", "diffuse = [0.7, 0.7, 0.7]\nexponent = 3.0");
  const std::string message = expectErrorAt(text, "exponent = 3.0");
  EXPECT_THAT(message, HasSubstr("unknown key 'exponent' in [materials.white] (type \"lambert\")"));
  EXPECT_THAT(message, HasSubstr("allowed keys: type, diffuse, emission"));
}

TEST_F(SceneFileTest, MissingKeyPointsAtItsTable) {
  const std::string text = replaced(kScene, "vertical_fov_deg = 39.3077\n", "");
  const std::string message = expectErrorAt(text, "[camera]");
  EXPECT_THAT(message, HasSubstr("missing key 'camera.vertical_fov_deg'"));
}

TEST_F(SceneFileTest, MissingMeshFile) {
  const std::string text = replaced(kScene, "file = \"quad.obj\"", "file = \"nowhere/quad.obj\"");
  const std::string message = expectErrorAt(text, "file = \"nowhere/quad.obj\"");
  // The path as resolved against the scene file's folder.
  EXPECT_THAT(message, HasSubstr((dir_ / "nowhere" / "quad.obj").string()));
  EXPECT_THAT(message, HasSubstr("does not exist"));
}

TEST_F(SceneFileTest, ObjWithoutTriangles) {
  writeFile(dir_ / "points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\n");
  const std::string text = replaced(kScene, "file = \"quad.obj\"", "file = \"points.obj\"");
  const std::string message = expectErrorAt(text, "file = \"points.obj\"");
  EXPECT_THAT(message, HasSubstr("has no triangles"));
  EXPECT_THAT(message, HasSubstr((dir_ / "points.obj").string()));
}

TEST_F(SceneFileTest, NegativeReflectance) {
  const std::string text =
      replaced(kScene, "diffuse = [0.7, 0.7, 0.7]", "diffuse = [0.7, -0.1, 0.7]");
  const std::string message = expectErrorAt(text, "diffuse = [0.7, -0.1, 0.7]");
  EXPECT_THAT(message, HasSubstr("materials.white.diffuse must not be negative"));
}

TEST_F(SceneFileTest, NanIsRejected) {
  const std::string text = replaced(kScene, "cone_angle_deg = 30.0", "cone_angle_deg = nan");
  const std::string message = expectErrorAt(text, "cone_angle_deg = nan");
  EXPECT_THAT(message, HasSubstr("lights[0].cone_angle_deg must be a finite number"));
}

TEST_F(SceneFileTest, EnergyGainIsRejected) {
  const std::string text =
      replaced(kScene, "specular = [0.4, 0.4, 0.4]", "specular = [0.4, 0.8, 0.4]");
  const std::string message = expectErrorAt(text, "specular = [0.4, 0.8, 0.4]");
  EXPECT_THAT(message, HasSubstr("materials.gloss reflects more light than it receives"));
}

TEST_F(SceneFileTest, OutOfRangeValues) {
  EXPECT_THAT(expectErrorAt(replaced(kScene, "width = 320", "width = 0"), "width = 0"),
              HasSubstr("image.width must be an integer"));
  EXPECT_THAT(
      expectErrorAt(replaced(kScene, "vertical_fov_deg = 39.3077", "vertical_fov_deg = 180"),
                    "vertical_fov_deg = 180"),
      HasSubstr("camera.vertical_fov_deg must be in (0, 180)"));
  EXPECT_THAT(
      expectErrorAt(replaced(kScene, "scale = [2.0, 3.0, 4.0]", "scale = -1"), "scale = -1"),
      HasSubstr("meshes[1].scale must be > 0"));
  EXPECT_THAT(
      expectErrorAt(replaced(kScene, "direction = [0.0, 0.0, -3.0]", "direction = [0.0, 0.0, 0.0]"),
                    "direction = [0.0, 0.0, 0.0]"),
      HasSubstr("lights[1].direction must not be zero"));
}

TEST_F(SceneFileTest, UnknownLightType) {
  const std::string text = replaced(kScene, "type = \"spot\"", "type = \"point\"");
  const std::string message = expectErrorAt(text, "type = \"point\"");
  EXPECT_THAT(message, HasSubstr("lights[0].type must be \"spot\" or \"directional\""));
}

TEST_F(SceneFileTest, MissingSceneFile) {
  try {
    loadSceneFile(dir_ / "absent.toml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("absent.toml"));
  }
}

}  // namespace
}  // namespace gib::scene::test
