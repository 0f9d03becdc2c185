// `stochastic_radiosity` end to end: a two-patch configuration with an analytic form factor, the
// Cornell box's error falling with iterations against the full reference, and determinism.
#include "realtime/techniques/stochastic_radiosity/stochastic_radiosity_technique.h"

#include "metrics/image_metrics.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/technique_runner.h"
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"
#include "support/form_factor.h"
#include "support/gl_test_context.h"
#include "support/statistical_test.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gib::rt {
namespace {

using test::pointToPolygonFormFactor;

// Two parallel unit squares one unit apart, face to face: the top one emits L^e = 1 downwards and
// reflects nothing, the bottom one reflects ρ = 0.5 and emits nothing.
constexpr float kAlbedo = 0.5f;
scene::Scene twoPatches() {
  scene::Material emitter, receiver;
  emitter.name = "emitter";
  emitter.emission = scene::Rgb(1.0f);
  receiver.name = "receiver";
  receiver.diffuse = scene::Rgb(kAlbedo);
  return test::facingUnitSquares(emitter, receiver);
}

// The area-to-area form factor of two directly opposed parallel unit squares one apart (Howell's
// catalogue, C-11, with X = Y = 1).
double opposedUnitSquaresFormFactor() {
  const double x = 1, y = 1, pi = std::numbers::pi;
  return 2 / (pi * x * y) *
         (0.5 * std::log((1 + x * x) * (1 + y * y) / (1 + x * x + y * y)) +
          x * std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y)) +
          y * std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) - x * std::atan(x) -
          y * std::atan(y));
}

class StochasticRadiosityTest : public test::GlTest {};

struct ReceiverResult {
  double mean_radiance = 0;      // area-weighted over the receiver's texels
  double expected_radiance = 0;  // ρ·L^e·F(x) at the same texels' sample points, same weights
};

ReceiverResult shootTwoPatches(const StochasticRadiositySettings& settings, int iterations) {
  const scene::Scene scene = twoPatches();
  GpuScene gpu_scene(scene, 16, 16);
  StochasticRadiosityTechnique technique(settings);
  technique.prepare(gpu_scene, 16, 16);
  gl::PassProfiler profiler;
  for (int i = 0; i < iterations; ++i) technique.step(profiler);
  const std::vector<glm::vec3> radiance = technique.atlasRadiance();
  const atlas::AtlasTexels& texels = technique.atlasTexels();
  const std::vector<glm::dvec3> emitter = {{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}};
  ReceiverResult r;
  double area = 0;
  for (std::size_t i = 0; i < texels.texels.size(); ++i) {
    const atlas::AtlasTexel& t = texels.texels[i];
    if (t.area <= 0 || t.triangle < 2) continue;  // triangles 2 and 3 are the receiver
    area += t.area;
    r.mean_radiance += t.area * radiance[i].g;
    r.expected_radiance +=
        t.area * kAlbedo *
        pointToPolygonFormFactor(glm::dvec3(t.position), glm::dvec3(t.normal), emitter);
  }
  r.mean_radiance /= area;
  r.expected_radiance /= area;
  return r;
}

// The transfer between the patches: after 400 iterations (about 360 shots from the emitter) the
// receiver's mean radiance matches ρ·L^e·F. The estimator's relative standard error there is
// 20%/√360 ≈ 1.05% (the shots' contributions to the mean vary by ~20% over the emitter), taken as
// known: a Z test, one for each projection, a family of two at 1%. The discretisation into texel
// centres changes the expected value by less than 0.1% (checked against the area-to-area form
// factor below).
constexpr test::TestFamily kTransferFamily(0.01, 2);
constexpr double kTransferRelativeStandardError = 0.2 / 18.97;  // 20% / √360

TEST_F(StochasticRadiosityTest, TwoPatchTransferMatchesTheAnalyticFormFactor) {
  const double area_to_area = kAlbedo * opposedUnitSquaresFormFactor();
  for (ShooterProjection projection :
       {ShooterProjection::kHemicube, ShooterProjection::kHemisphere}) {
    StochasticRadiositySettings settings;
    settings.atlas_resolution = 64;
    settings.projection = projection;
    // The hemispherical projection draws straight edges between projected vertices: the squares
    // must be finely tessellated for its visibility to hold (the paper's caveat).
    settings.tessellation = projection == ShooterProjection::kHemisphere ? 4 : 0;
    const ReceiverResult r = shootTwoPatches(settings, 400);
    std::printf("%s: receiver %.5f, expected %.5f (area to area %.5f)\n",
                projection == ShooterProjection::kHemicube ? "hemicube" : "hemisphere",
                r.mean_radiance, r.expected_radiance, area_to_area);
    EXPECT_NEAR(r.expected_radiance, area_to_area, 1e-3 * area_to_area);
    EXPECT_TRUE(kTransferFamily.zTest(r.mean_radiance, r.expected_radiance,
                                      kTransferRelativeStandardError * r.expected_radiance));
  }
}

// The hemicube's side faces (layers 1..4 of the visibility map, drawn by one instanced draw into
// the lower half of their layers) see what lies more than 45° off the shooter's normal. Two
// receivers on the floor beside a ceiling emitter are seen only through them (63°–76° off); a
// black wall hides one completely, so it must stay exactly dark while the other, in the open,
// receives about ρ·L^e·F (at least half of it after 300 iterations: a broken side face reads as
// all-visible or all-hidden and fails one receiver or the other).
TEST_F(StochasticRadiosityTest, HemicubeSideFacesHideWhatAWallHides) {
  scene::Material emitter, receiver, black;
  emitter.name = "emitter";
  emitter.emission = scene::Rgb(1.0f);
  receiver.name = "receiver";
  receiver.diffuse = scene::Rgb(kAlbedo);
  black.name = "black";
  scene::Scene s;
  s.name = "wall between emitter and receiver";
  s.camera.position = {0.5f, 3.0f, -6.0f};
  s.camera.look_at = {0.5f, 0.5f, 0.5f};
  s.materials = {emitter, receiver, black};
  scene::Mesh light, hidden, open, wall;
  light.material = 0;
  hidden.material = open.material = 1;
  wall.material = 2;
  scene::appendQuad(light, {0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1});     // normal −y
  scene::appendQuad(hidden, {3, 0, 0}, {3, 0, 1}, {4, 0, 1}, {4, 0, 0});    // normal +y
  scene::appendQuad(open, {-3, 0, 0}, {-3, 0, 1}, {-2, 0, 1}, {-2, 0, 0});  // normal +y
  scene::appendQuad(wall, {2, -0.5f, -1}, {2, 1.5f, -1}, {2, 1.5f, 2}, {2, -0.5f, 2});
  s.meshes = {light, hidden, open, wall};
  GpuScene gpu_scene(s, 16, 16);
  StochasticRadiositySettings settings;
  settings.atlas_resolution = 64;
  StochasticRadiosityTechnique technique(settings);
  technique.prepare(gpu_scene, 16, 16);
  gl::PassProfiler profiler;
  for (int i = 0; i < 300; ++i) technique.step(profiler);
  const std::vector<glm::vec3> radiance = technique.atlasRadiance();
  const atlas::AtlasTexels& texels = technique.atlasTexels();
  const std::vector<glm::dvec3> emitter_corners = {{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}};
  double hidden_max = 0, open_mean = 0, open_expected = 0, open_area = 0;
  int hidden_texels = 0;
  for (std::size_t i = 0; i < texels.texels.size(); ++i) {
    const atlas::AtlasTexel& t = texels.texels[i];
    if (t.area <= 0) continue;
    if (t.triangle == 2 || t.triangle == 3) {  // the hidden receiver
      hidden_max = std::max(hidden_max, double(radiance[i].g));
      ++hidden_texels;
    } else if (t.triangle == 4 || t.triangle == 5) {  // the open one
      open_area += t.area;
      open_mean += t.area * radiance[i].g;
      open_expected +=
          t.area * kAlbedo *
          pointToPolygonFormFactor(glm::dvec3(t.position), glm::dvec3(t.normal), emitter_corners);
    }
  }
  ASSERT_GT(hidden_texels, 50);
  ASSERT_GT(open_area, 0.5);
  open_mean /= open_area;
  open_expected /= open_area;
  std::printf("hidden receiver: largest %.3g; open receiver %.5f, expected %.5f\n", hidden_max,
              open_mean, open_expected);
  EXPECT_EQ(hidden_max, 0.0);
  EXPECT_GT(open_mean, 0.5 * open_expected);
  EXPECT_LT(open_mean, 1.5 * open_expected);
}

// Spot lights are injected as first-bounce light (light_injection.h): before any iteration every
// texel of a floor under a spot light holds ρ/π · I · cos θ / d², the analytic reflected radiance
// (the floor cannot shadow itself, so only the shadow map's bias could make a texel dark).
TEST_F(StochasticRadiosityTest, SpotLightIsInjectedWithItsAnalyticReflectedRadiance) {
  scene::Scene s;
  s.name = "spot_over_floor";
  s.camera.position = {0.5f, 2.0f, -2.0f};
  s.camera.look_at = {0.5f, 0.0f, 0.5f};
  scene::Material floor_material;
  floor_material.name = "floor";
  floor_material.diffuse = scene::Rgb(kAlbedo);
  s.materials = {floor_material};
  scene::Mesh floor;
  scene::appendQuad(floor, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0});  // normal +y
  s.meshes = {floor};
  scene::SpotLight spot;
  spot.position = {0.5f, 1.0f, 0.5f};
  spot.direction = {0.0f, -1.0f, 0.0f};
  spot.intensity = scene::Rgb(2.0f);
  spot.cone_angle_deg = 80.0f;  // the whole floor is inside the cone
  s.spot_lights = {spot};

  GpuScene gpu_scene(s, 16, 16);
  StochasticRadiositySettings settings;
  settings.atlas_resolution = 64;
  StochasticRadiosityTechnique technique(settings);
  technique.prepare(gpu_scene, 16, 16);
  const std::vector<glm::vec3> radiance = technique.atlasRadiance();
  const atlas::AtlasTexels& texels = technique.atlasTexels();
  int checked = 0;
  for (std::size_t i = 0; i < texels.texels.size(); ++i) {
    const atlas::AtlasTexel& t = texels.texels[i];
    if (t.area <= 0) continue;
    const glm::vec3 to_light = spot.position - t.position;
    const float d = glm::length(to_light);
    const float expected = kAlbedo / std::numbers::pi_v<float> * 2.0f * (to_light.y / d) / (d * d);
    EXPECT_NEAR(radiance[i].g, expected, 0.01f * expected) << "texel " << i;
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

TechniqueRunSettings smallRun(int iterations) {
  TechniqueRunSettings settings;
  settings.width = 32;
  settings.height = 32;
  settings.warmup_frames = 0;
  settings.frames = 1;
  settings.iterations = iterations;
  settings.context.debug = true;
  return settings;
}

image::Image renderCornell(int iterations, const std::vector<std::string>& set = {"atlas=64"}) {
  const scene::Scene scene = scene::loadScene("cornell", {});
  const TechniqueInfo& info = findTechnique("stochastic_radiosity");
  const ParameterValues values = parseParameters(info.parameters, set, "technique");
  TechniqueRunResult result = runTechnique(scene, info, values, smallRun(iterations));
  EXPECT_EQ(result.iterations, iterations);
  EXPECT_EQ(result.path_class, (scene::PathClass{0, scene::PathClass::kUnlimited}));
  return result.image;
}

// Against the full reference (all paths), the error after 200 iterations is below the error after
// 10: the stochastic iteration converges towards the atlas's discretisation floor.
TEST(StochasticRadiosity, CornellErrorFallsWithIterations) {
  const scene::Scene scene = scene::loadScene("cornell", {});
  ref::RenderSettings settings;
  settings.width = 32;
  settings.height = 32;
  settings.spp = 512;
  const ref::RenderResult reference = ref::renderReference(scene, settings);
  const double error_10 = metrics::computeRelMse(reference.mean, renderCornell(10)).value;
  const double error_200 = metrics::computeRelMse(reference.mean, renderCornell(200)).value;
  std::printf("relMSE after 10 iterations %.4f, after 200 %.4f\n", error_10, error_200);
  EXPECT_LT(error_200, error_10);
}

TEST(StochasticRadiosity, AFixedSeedGivesTheSameImageEveryRun) {
  const image::Image a = renderCornell(20), b = renderCornell(20);
  const image::Image c = renderCornell(20, {"atlas=64", "seed=1"});
  EXPECT_TRUE(std::equal(a.data().begin(), a.data().end(), b.data().begin()));
  EXPECT_FALSE(std::equal(a.data().begin(), a.data().end(), c.data().begin()));
}

// The GPU commands of an iteration at the book's 128² atlas: the descent over every pyramid level
// in one dispatch, the five hemicube faces in one instanced draw, the update, and the pyramid in
// two dispatches of four levels each (it was 7 + 5 + 1 + 7 = 20). More means a pass per level or
// per face came back.
TEST(StochasticRadiosity, GpuCommandsPerIterationStayWithinTheirBound) {
  const scene::Scene scene = scene::loadScene("cornell", {});
  const TechniqueInfo& info = findTechnique("stochastic_radiosity");
  const ParameterValues values = parseParameters(info.parameters, {"atlas=128"}, "technique");
  const TechniqueRunResult result = runTechnique(scene, info, values, smallRun(3));
  ASSERT_FALSE(result.iteration_profile.passes.empty());
  const PassRecord& iteration = result.iteration_profile.passes.front();
  ASSERT_EQ(iteration.gpu_commands.size(), 3u);
  for (int commands : iteration.gpu_commands) EXPECT_EQ(commands, 5);
}

}  // namespace
}  // namespace gib::rt
