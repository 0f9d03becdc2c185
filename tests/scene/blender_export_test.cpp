// The Blender script of a scene: its data are the scene's own numbers in Blender's conventions,
// the emitters' back faces emit nothing, and what Cycles cannot reproduce exactly is reported.
#include "scene/blender_export.h"

#include "common/input_error.h"
#include "scene/builtin_scenes.h"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numbers>

namespace gib::scene {
namespace {

using ::testing::HasSubstr;
using ::testing::IsEmpty;
using ::testing::Not;
using ::testing::SizeIs;

BlenderExportSettings smallSettings() {
  BlenderExportSettings s;
  s.width = 64;
  s.height = 48;
  s.spp = 16;
  s.seed = 7;
  return s;
}

std::string vec(float x, float y, float z) {
  return fmt::format("({}, {}, {})", x, y, z);
}

TEST(BlenderExport, CornellBoxMapsExactlyWithItsCameraMaterialsAndSettings) {
  const Scene scene = loadScene("cornell", {"blocks=false"});
  const BlenderExport out = exportBlenderScript(scene, smallSettings());
  EXPECT_THAT(out.warnings, IsEmpty());
  const std::string& py = out.script;
  EXPECT_THAT(py, HasSubstr("Every part of the scene maps exactly"));
  EXPECT_THAT(py, HasSubstr("hash " + hashScene(scene) + ", blocks=false"));
  EXPECT_THAT(py, HasSubstr("\"render\": {\"width\": 64, \"height\": 48, \"spp\": 16, "
                            "\"seed\": 7, \"max_bounces\": 1024}"));
  // The camera: GI Bench's frame (looking down +z, +x to the image's left) and vertical FOV.
  EXPECT_THAT(py, HasSubstr("\"position\": " + vec(278, 273, -800)));
  EXPECT_THAT(py, HasSubstr("\"forward\": " + vec(0, 0, 1)));
  EXPECT_THAT(py, HasSubstr("\"right\": " + vec(-1, 0, 0)));
  EXPECT_THAT(py, HasSubstr("\"up\": " + vec(0, 1, 0)));
  EXPECT_THAT(py,
              HasSubstr(fmt::format("\"vertical_fov_deg\": {}", scene.camera.vertical_fov_deg)));
  EXPECT_THAT(py, HasSubstr("camera.sensor_fit = \"VERTICAL\""));
  // Every material's reflectance, and the light's radiance on its front face only.
  for (const Material& m : scene.materials) {
    const Rgb& d = m.diffuse;
    EXPECT_THAT(py, HasSubstr(fmt::format("\"name\": \"{}\", \"diffuse\": {}, \"glossy\": None",
                                          m.name, vec(d.r, d.g, d.b))));
  }
  const Rgb& e = scene.materials.at(3).emission;
  EXPECT_THAT(py, HasSubstr("\"emission\": " + vec(e.r, e.g, e.b)));
  EXPECT_THAT(py, HasSubstr("links.new(geometry.outputs[\"Backfacing\"], sides.inputs[\"Fac\"])"));
  // Unbiased, unfiltered, unprocessed.
  for (const char* setting :
       {"pixel_filter_type = \"BOX\"", "filter_width = 1.0", "sample_clamp_direct = 0.0",
        "sample_clamp_indirect = 0.0", "use_denoising = False", "use_adaptive_sampling = False",
        "blur_glossy = 0.0", "view_transform = \"Standard\"", "film_transparent = False",
        "color_depth = \"32\""})
    EXPECT_THAT(py, HasSubstr(setting));
  // Five walls and the light, each with its triangles as they are.
  EXPECT_EQ(scene.meshes.size(), 6u);
  EXPECT_THAT(py, HasSubstr("\"triangles\": [0, 1, 2, 0, 2, 3]"));
}

TEST(BlenderExport, LampsKeepGiBenchsUnits) {
  Scene scene = loadScene("cornell", {"blocks=false"});
  SpotLight spot;
  spot.position = {100, 500, 200};
  spot.direction = {0, -2, 0};
  spot.intensity = {2000, 1000, 500};  // W/sr
  spot.cone_angle_deg = 30;
  spot.falloff_exponent = 1;  // Blender's spot lamp: I·cos θ inside the cone
  scene.spot_lights.push_back(spot);
  scene.directional_lights.push_back({{0, 0, 1}, {3, 1.5f, 0}});
  scene.sky_radiance = {0.25f, 0.5f, 1};
  const BlenderExport out = exportBlenderScript(scene, smallSettings());
  EXPECT_THAT(out.warnings, IsEmpty());
  const std::string& py = out.script;
  // Cycles emits P/(4π) W/sr from a spot lamp of P watts.
  EXPECT_DOUBLE_EQ(blenderLampWatts(1.0), 4 * std::numbers::pi);
  EXPECT_THAT(
      py, HasSubstr(fmt::format("\"direction\": {}, \"color\": {}, \"watts\": {}", vec(0, -1, 0),
                                vec(1, 0.5f, 0.25f), float(blenderLampWatts(2000)))));
  EXPECT_THAT(py, HasSubstr(fmt::format("\"spot_size\": {}, \"spot_blend\": 0.0",
                                        float(std::numbers::pi / 3))));
  // A sun's strength is the irradiance on a perpendicular plane.
  EXPECT_THAT(py, HasSubstr("{\"direction\": " + vec(0, 0, 1) + ", \"color\": " + vec(1, 0.5f, 0) +
                            ", \"strength\": 3}"));
  EXPECT_THAT(py, HasSubstr("\"sky\": " + vec(0.25f, 0.5f, 1)));
  // Any other fall-off, a uniform cone included, is not Blender's.
  scene.spot_lights[0].falloff_exponent = 0;
  const BlenderExport uniform = exportBlenderScript(scene, smallSettings());
  ASSERT_THAT(uniform.warnings, SizeIs(1));
  EXPECT_THAT(uniform.warnings[0], HasSubstr("k = 0, Blender's spot lamp as cos (k = 1)"));
  EXPECT_THAT(uniform.warnings[0], HasSubstr("darker off its axis"));
}

TEST(BlenderExport, SaysWhatCyclesCannotReproduce) {
  // The chamber: Phong floor and pillars, a spot light with cos² fall-off.
  const BlenderExport chamber = exportBlenderScript(loadScene("chamber"), smallSettings());
  ASSERT_THAT(chamber.warnings, SizeIs(2));
  EXPECT_THAT(chamber.warnings[0], HasSubstr("Phong material"));
  EXPECT_THAT(chamber.warnings[1], HasSubstr("cos^k with k = 2"));
  EXPECT_THAT(chamber.warnings[1], HasSubstr("brighter off its axis"));
  EXPECT_THAT(chamber.script, HasSubstr("# Not exact: Phong material"));
  EXPECT_THAT(chamber.script, HasSubstr("\"glossy\": {\"color\": "));
  // The cloud: a medium, which is left out.
  const BlenderExport cloud = exportBlenderScript(loadScene("cloud"), smallSettings());
  ASSERT_THAT(cloud.warnings, SizeIs(1));
  EXPECT_THAT(cloud.warnings[0], HasSubstr("medium"));
}

TEST(BlenderExport, PhongExponentBecomesBeckmannRoughness) {
  // α = √(2/(n+2)) and Cycles squares its roughness: r = α^½.
  EXPECT_DOUBLE_EQ(phongToBeckmannRoughness(0), 1.0);
  EXPECT_NEAR(phongToBeckmannRoughness(14), std::pow(0.125, 0.25), 1e-12);
  EXPECT_LT(phongToBeckmannRoughness(1000), 0.22);
}

TEST(BlenderExport, RefusesSettingsCyclesCannotTake) {
  const Scene scene = loadScene("cornell");
  BlenderExportSettings s = smallSettings();
  s.spp = 0;
  EXPECT_THROW(exportBlenderScript(scene, s), InputError);
  s = smallSettings();
  s.height = 0;
  EXPECT_THROW(exportBlenderScript(scene, s), InputError);
  s = smallSettings();
  s.seed = 2147483648u;
  EXPECT_THROW(exportBlenderScript(scene, s), InputError);
  s.seed = 2147483647u;
  EXPECT_THAT(exportBlenderScript(scene, s).script, Not(IsEmpty()));
}

}  // namespace
}  // namespace gib::scene
