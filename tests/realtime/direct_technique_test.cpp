// `direct` against the reference restricted to its path class (LE|LDE): each light type on a
// plane, where shadow maps see no occluder and the result must match, and the Cornell box, where
// the error must fall as light samples grow.
#include "realtime/technique_runner.h"

#include "metrics/image_metrics.h"
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"
#include "support/render_statistics.h"
#include "support/statistical_test.h"
#include "support/technique_frame.h"

#include <gtest/gtest.h>

#include <cmath>

namespace gib::rt {
namespace {

TechniqueRunSettings smallRun(int width, int height) {
  TechniqueRunSettings settings;
  settings.width = width;
  settings.height = height;
  settings.warmup_frames = 0;
  settings.frames = 1;
  settings.context.debug = true;  // any GL error fails the run
  return settings;
}

image::Image renderDirect(const scene::Scene& scene, const std::vector<std::string>& set, int width,
                          int height) {
  const TechniqueInfo& info = findTechnique("direct");
  const ParameterValues values = parseParameters(info.parameters, set, "technique 'direct'");
  TechniqueRunResult result = runTechnique(scene, info, values, smallRun(width, height));
  EXPECT_EQ(result.path_class, (scene::PathClass{0, 1}));
  return result.image;
}

ref::RenderResult renderDirectReference(const scene::Scene& scene, int width, int height,
                                        std::uint32_t spp) {
  ref::RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.spp = spp;
  settings.path_class = {0, 1};
  return ref::renderReference(scene, settings);
}

double meanOf(const image::Image& image) {
  double sum = 0;
  for (float v : image.data()) sum += v;
  return sum / double(image.data().size());
}

// A correct technique misses one of this file's five comparisons with the reference's image mean
// (expectMatchesReference's calls) with probability 1%.
constexpr test::TestFamily kFamily(0.01, 5);

// Within the class, a light that nothing occludes must be reproduced: the image mean agrees
// with the reference's by a t test on its standard error (test::imageMean: the channels of a
// pixel are not independent; Student's t with the pixels' pooled degrees of freedom), allowing
// 0.5% for the difference between GL's pixel-centre sample and the reference's pixel-area
// average; the per-pixel relative error is small everywhere.
void expectMatchesReference(const scene::Scene& scene, const std::vector<std::string>& set,
                            double pixel_mape) {
  const int w = 48, h = 48;
  const image::Image test = renderDirect(scene, set, w, h);
  const ref::RenderResult reference = renderDirectReference(scene, w, h, 64);
  const test::ImageMean truth = test::imageMean(reference);
  const double m_test = meanOf(test), m_ref = truth.mean;
  EXPECT_GT(m_ref, 0.0);
  EXPECT_TRUE(kFamily.tTest(m_test, m_ref, truth.standard_error, truth.dof, 0.005 * m_ref));
  const double mape = metrics::computeMape(reference.mean, test).value;
  EXPECT_LT(mape, pixel_mape);
  EXPECT_EQ(image::countNonFinite(test), 0u);
}

TEST(DirectTechnique, DirectionalLightOnAPlaneMatchesTheReference) {
  scene::Scene scene = test::floorScene();
  scene.directional_lights.push_back({glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f)), {2, 1, 0.5f}});
  for (const char* shadow : {"shadow=hard", "shadow=pcf", "shadow=vsm"})
    expectMatchesReference(scene, {shadow}, 0.03);
}

TEST(DirectTechnique, SpotLightOnAPlaneMatchesTheReference) {
  scene::Scene scene = test::floorScene();
  scene::SpotLight spot;
  spot.position = {0.5f, 1.5f, 0.0f};
  spot.direction = {0.0f, -1.0f, 0.0f};
  spot.intensity = {3, 3, 3};
  spot.cone_angle_deg = 70.0f;
  spot.falloff_exponent = 2.0f;
  scene.spot_lights.push_back(spot);
  // The cone's hard edge crosses pixels, where centre and area average differ.
  expectMatchesReference(scene, {"shadow=pcf"}, 0.05);
}

TEST(DirectTechnique, SkyOnAPlaneMatchesTheReferenceWithManyDirections) {
  scene::Scene scene = test::floorScene();
  scene.sky_radiance = scene::Rgb(1.0f, 0.8f, 0.6f);
  expectMatchesReference(scene, {"light_samples=256", "shadow_map_size=64"}, 0.03);
}

// Error of `direct` against the reference direct-only Cornell box as light samples grow: the
// area light's penumbrae converge, then the error levels off at what shadow maps and one sample
// per pixel (against the reference's pixel-area average) leave. The reference is a fixed render
// (seed 0), so the comparisons are deterministic.
TEST(DirectTechnique, CornellErrorFallsAsLightSamplesGrow) {
  const scene::Scene scene = scene::loadScene("cornell", {});
  const int w = 64, h = 64;
  const ref::RenderResult reference = renderDirectReference(scene, w, h, 256);
  std::vector<double> errors, mape;
  for (int n : {1, 4, 16, 64}) {
    const image::Image test =
        renderDirect(scene, {"shadow=pcf", "light_samples=" + std::to_string(n)}, w, h);
    errors.push_back(metrics::computeRelMse(reference.mean, test).value);
    mape.push_back(metrics::computeMape(reference.mean, test).value);
    std::printf("light_samples=%d relMSE=%.5f MAPE=%.4f\n", n, errors.back(), mape.back());
  }
  EXPECT_LT(errors[1], 0.5 * errors[0]);
  for (std::size_t i = 2; i < errors.size(); ++i) EXPECT_LT(errors[i], 1.02 * errors[i - 1]) << i;
  EXPECT_LT(mape.back(), 0.06);
}

// The GPU commands of a frame (draws and dispatches, what a real GPU's per-command overhead
// scales with): with the Cornell box's 16 area-light samples in one batch, one G-buffer draw, one
// emission draw, one instanced shadow draw for every face of the batch and one shading draw.
// More means a pass was added per sample or per face (before batching it was 2 + 16 × (5 + 1)).
TEST(DirectTechnique, GpuCommandsPerFrameStayWithinTheirBound) {
  const scene::Scene scene = scene::loadScene("cornell", {});
  const TechniqueInfo& info = findTechnique("direct");
  const ParameterValues values =
      parseParameters(info.parameters, {"light_samples=16"}, "technique 'direct'");
  TechniqueRunSettings settings = smallRun(32, 32);
  settings.frames = 2;
  const TechniqueRunResult result = runTechnique(scene, info, values, settings);
  const PassRecord& frame = result.profile.passes.front();
  ASSERT_EQ(frame.gpu_commands.size(), 2u);
  EXPECT_GT(frame.gpu_commands[0], 0);
  EXPECT_EQ(frame.gpu_commands[0], frame.gpu_commands[1]) << "the same work every frame";
  EXPECT_LE(frame.gpu_commands[0], 4);
}

}  // namespace
}  // namespace gib::rt
