// The Blender script of a scene: its data are the scene's own numbers in Blender's conventions,
// the emitters' back faces emit nothing, mirrors, glass and shading normals map onto Cycles'
// sharp BSDFs, volume absorption and custom normals, and what Cycles cannot reproduce exactly is
// reported. (tests/scripts/blender_builder_test.sh renders the builder's materials in Blender.)
#include "scene/blender_export.h"

#include "common/input_error.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

namespace gib::scene {
namespace {

using ::testing::ElementsAre;
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

// The thin lens goes to Cycles' depth of field (an f-stop from the focal length, a round
// aperture, the same focus distance; scene/blender_scene.py); a pinhole's camera has no lens keys,
// so its export is as it was. The focus distance in effect is written: look_at's by default.
TEST(BlenderExport, TheThinLensIsExportedOnlyWhenThereIsOne) {
  Scene scene = loadScene("cornell", {"blocks=false"});
  EXPECT_THAT(exportBlenderScript(scene, smallSettings()).script,
              Not(HasSubstr("\"lens_radius\": ")));
  scene.camera.lens_radius = 25;
  const std::string py = exportBlenderScript(scene, smallSettings()).script;
  EXPECT_THAT(py, HasSubstr("\"lens_radius\": 25, \"focus_distance\": 800}"));
  EXPECT_THAT(py, HasSubstr("camera.dof.aperture_fstop = camera.lens * 1e-3 / (2.0 * "
                            "spec[\"lens_radius\"])"));
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

// The empty Cornell box with a quad of material `m` on the floor, shaded smooth when `normals`.
Scene boxWithQuad(const Material& m, bool normals) {
  Scene scene = loadScene("cornell", {"blocks=false"});
  scene.materials.push_back(m);
  Mesh quad;
  quad.name = m.name + "_quad";
  quad.material = std::uint32_t(scene.materials.size() - 1);
  appendQuad(quad, {200, 1, 200}, {200, 1, 300}, {300, 1, 300}, {300, 1, 200});
  if (normals)
    quad.normals = {glm::normalize(glm::vec3(0.5f, 1, 0)), {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
  scene.meshes.push_back(quad);
  return scene;
}

TEST(BlenderExport, MirrorsAreSharpGlossyWithTheConductorsFresnel) {
  Material gold;
  gold.name = "gold";
  gold.type = MaterialType::kMirror;
  gold.diffuse = Rgb(0.5f);  // ignored: a mirror has no diffuse part
  gold.conductor_n = {0.18f, 0.42f, 1.37f};
  gold.conductor_k = {3.42f, 2.35f, 1.77f};
  const BlenderExport conductor = exportBlenderScript(boxWithQuad(gold, false), smallSettings());
  EXPECT_THAT(conductor.warnings, IsEmpty());
  EXPECT_THAT(conductor.script,
              HasSubstr("{\"name\": \"gold\", \"diffuse\": None, \"glossy\": None, \"mirror\": "
                        "{\"n\": " +
                        vec(0.18f, 0.42f, 1.37f) + ", \"k\": " + vec(3.42f, 2.35f, 1.77f) +
                        "}, \"glass\": None, \"emission\": None}"));
  // The builder: a Sharp Glossy BSDF coloured by the Fresnel graph, with the shading normal's
  // cosine; and the Cornell box's own materials stay Lambertian.
  for (const char* builder :
       {"mirror.distribution = \"SHARP\"", "def conductor_fresnel(tree, n, k):",
        "links.new(geometry.outputs[\"Normal\"], dot.inputs[0])",
        "tree.links.new(geometry.outputs[\"Incoming\"], dot.inputs[1])",
        "caustics_reflective = True"})
    EXPECT_THAT(conductor.script, HasSubstr(builder));
  EXPECT_THAT(conductor.script, HasSubstr("\"name\": \"white\", \"diffuse\": ("));

  Material perfect = gold;
  perfect.name = "perfect";
  perfect.perfect_mirror = true;
  const BlenderExport ideal = exportBlenderScript(boxWithQuad(perfect, false), smallSettings());
  EXPECT_THAT(ideal.warnings, IsEmpty());
  EXPECT_THAT(ideal.script, HasSubstr("\"mirror\": \"perfect\", \"glass\": None"));
}

TEST(BlenderExport, GlassIsSharpGlassWithBeerLambertAbsorptionInside) {
  Material glass;
  glass.name = "glass";
  glass.type = MaterialType::kGlass;
  glass.ior = 1.5f;
  const BlenderExport clear = exportBlenderScript(boxWithQuad(glass, false), smallSettings());
  EXPECT_THAT(clear.warnings, IsEmpty());
  EXPECT_THAT(clear.script, HasSubstr("\"diffuse\": None, \"glossy\": None, \"mirror\": None, "
                                      "\"glass\": {\"ior\": 1.5, \"absorption\": None}"));
  glass.absorption = {0.004f, 0.001f, 0.0f};
  glass.ior = 1.33f;
  const BlenderExport tinted = exportBlenderScript(boxWithQuad(glass, false), smallSettings());
  EXPECT_THAT(tinted.warnings, IsEmpty());
  // density 0.004, colour 1 − a/0.004.
  EXPECT_THAT(tinted.script, HasSubstr("\"glass\": {\"ior\": 1.33, \"absorption\": {\"color\": " +
                                       vec(0, 0.75f, 1) + ", \"density\": 0.004}}"));
  for (const char* builder :
       {"glass = nodes.new(\"ShaderNodeBsdfGlass\")", "glass.distribution = \"SHARP\"",
        "nodes.new(\"ShaderNodeVolumeAbsorption\")", "homogeneous_volume = True",
        "output.inputs[\"Volume\"]", "caustics_refractive = True",
        "cycles.transmission_bounces = bounces", "cycles.transparent_max_bounces = bounces"})
    EXPECT_THAT(tinted.script, HasSubstr(builder));
}

TEST(BlenderExport, AbsorptionBecomesDensityTimesOneMinusColour) {
  const CyclesAbsorption a = cyclesAbsorption({0.02f, 0.005f, 0.0f});
  EXPECT_EQ(a.density, 0.02f);
  EXPECT_EQ(a.color, Rgb(0.0f, 0.75f, 1.0f));
  // Cycles' σ = ρ·(1 − C), computed in float as Cycles does, is the absorption up to C's rounding
  // to a float (below 2⁻²⁴·ρ, blender_export.h) and the rounding of Cycles' own float product
  // (half an ulp of σ ≤ ρ, at most 2⁻²⁴·ρ): 2⁻²³·ρ in all.
  std::mt19937 random(43);
  std::uniform_real_distribution<float> coefficient(0.0f, 1.0f);
  std::uniform_int_distribution<int> scale(-6, 2);
  for (int trial = 0; trial < 1000; ++trial) {
    const float unit = std::ldexp(1.0f, scale(random));
    const Rgb absorption(coefficient(random) * unit, coefficient(random) * unit,
                         coefficient(random) * unit);
    if (std::max({absorption.r, absorption.g, absorption.b}) <= 0) continue;
    const CyclesAbsorption c = cyclesAbsorption(absorption);
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(c.color[k], 0.0f);
      EXPECT_LE(c.color[k], 1.0f);
      EXPECT_NEAR(c.density * (1.0f - c.color[k]), absorption[k], std::ldexp(c.density, -23))
          << "trial " << trial << ", channel " << k;
    }
  }
  EXPECT_THROW(cyclesAbsorption(Rgb(0.0f)), std::logic_error);
}

TEST(BlenderExport, ShadingNormalsBecomeCustomSplitNormals) {
  Material white;
  white.name = "matte";
  white.diffuse = Rgb(0.5f);
  const BlenderExport smooth = exportBlenderScript(boxWithQuad(white, true), smallSettings());
  EXPECT_THAT(smooth.warnings, IsEmpty());
  const glm::vec3 tilted = glm::normalize(glm::vec3(0.5f, 1, 0));
  EXPECT_THAT(smooth.script,
              HasSubstr(fmt::format("\"normals\": [{}, {}, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0],",
                                    tilted.x, tilted.y)));
  for (const char* builder :
       {"mesh.use_auto_smooth = True", "mesh.normals_split_custom_set_from_vertices(",
        "foreach_set(\"use_smooth\", [normals is not None] * count)"})
    EXPECT_THAT(smooth.script, HasSubstr(builder));
  // Flat meshes (the box's walls) have none.
  EXPECT_THAT(smooth.script, HasSubstr("\"normals\": None,"));
}

TEST(BlenderExport, WarnsThatCyclesMissesCausticsOfPointAndDirectionalLamps) {
  Material mirror;
  mirror.name = "mirror";
  mirror.type = MaterialType::kMirror;
  mirror.perfect_mirror = true;
  Scene scene = boxWithQuad(mirror, false);
  SpotLight spot;
  spot.intensity = Rgb(100.0f);
  spot.falloff_exponent = 1;
  scene.spot_lights.push_back(spot);
  const BlenderExport with_spot = exportBlenderScript(scene, smallSettings());
  ASSERT_THAT(with_spot.warnings, SizeIs(1));
  EXPECT_THAT(with_spot.warnings[0], HasSubstr("the spot lamps' caustics"));
  EXPECT_THAT(with_spot.script, HasSubstr("# Not exact: the spot lamps' caustics"));
  scene.directional_lights.push_back({{0, -1, 0}, Rgb(1.0f)});
  EXPECT_THAT(exportBlenderScript(scene, smallSettings()).warnings,
              ElementsAre(HasSubstr("the spot and sun lamps' caustics")));
  // No mirror or glass, or only a black lamp: nothing is missing.
  scene.materials.back().type = MaterialType::kLambert;
  EXPECT_THAT(exportBlenderScript(scene, smallSettings()).warnings, IsEmpty());
  scene.materials.back().type = MaterialType::kMirror;
  scene.directional_lights.clear();
  scene.spot_lights[0].intensity = Rgb(0.0f);
  EXPECT_THAT(exportBlenderScript(scene, smallSettings()).warnings, IsEmpty());
}

TEST(BlenderExport, PhongExponentBecomesBeckmannRoughness) {
  // α = √(2/(n+2)) and Cycles squares its roughness: r = α^½.
  EXPECT_DOUBLE_EQ(phongToBeckmannRoughness(0), 1.0);
  EXPECT_NEAR(phongToBeckmannRoughness(14), std::pow(0.125, 0.25), 1e-12);
  EXPECT_LT(phongToBeckmannRoughness(1000), 0.22);
}

TEST(BlenderExport, EnvironmentMapIsItsTexelsBottomRowFirstThroughTheAxisChange) {
  Scene scene = loadScene("cornell");
  EXPECT_THAT(exportBlenderScript(scene, smallSettings()).script,
              HasSubstr("\"environment\": None"));
  scene.sky_radiance = Rgb(0.0f);
  // Texel (x, y) holds 10·y + x in red: rows 0 (up) and 1 (down) of a 4 × 2 map.
  std::vector<float> texels;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) texels.insert(texels.end(), {float(10 * y + x), 0.0f, 0.0f});
  scene.environment = makeEnvironmentMap(4, 2, texels, "test");
  scene.environment.intensity = 2.0f;
  const std::string script = exportBlenderScript(scene, smallSettings()).script;
  // Blender's first row is its bottom: GI Bench's row 1 (10..13) comes first.
  EXPECT_THAT(script, HasSubstr("\"pixels\": [10,0,0,1,11,0,0,1,12,0,0,1,13,0,0,1,0,0,0,1,1,"));
  EXPECT_THAT(script, HasSubstr("{\"width\": 4, \"height\": 2, \"strength\": 2,"));
  // D = (−m.x, m.z, m.y): world +y (the map's up) becomes Blender's +z, and world +x, where
  // GI Bench's u = 0 lies, becomes −x, where Blender's u = ½ − atan2(y, x)/2π is 0 too.
  EXPECT_THAT(script, HasSubstr("\"matrix\": [[-1, 0, 0], [0, 0, 1], [0, 1, 0]]"));
  // Turned by 90° (+x towards −z), world −z sees what the map holds at +x (Blender's −x) and
  // world +x what it holds at −z (m.z = −1: Blender's −y).
  scene.environment.rotation_deg = 90.0f;
  const std::string turned = exportBlenderScript(scene, smallSettings()).script;
  const std::size_t at = turned.find("\"matrix\": [[");
  ASSERT_NE(at, std::string::npos);
  float m[3][3];
  ASSERT_EQ(
      std::sscanf(turned.c_str() + at, "\"matrix\": [[%f, %f, %f], [%f, %f, %f], [%f, %f, %f]]",
                  &m[0][0], &m[0][1], &m[0][2], &m[1][0], &m[1][1], &m[1][2], &m[2][0], &m[2][1],
                  &m[2][2]),
      9);
  const float expected[3][3] = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(m[r][c], expected[r][c], 1e-6f) << r << "," << c;
  const glm::vec3 minus_z = glm::vec3(m[0][2], m[1][2], m[2][2]) * -1.0f;
  EXPECT_NEAR(minus_z.x, -1.0f, 1e-6f) << "world -z looks up Blender's -x";
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
