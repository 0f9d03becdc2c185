// `jittered_light_sampling` against the reference restricted to its path class (LE|LDE): an
// area light over a plane, where nothing occludes and the result must match, and the Cornell
// box, where its penumbrae must beat `direct`'s sixteen shadow-mapped light samples.
#include "realtime/technique_runner.h"

#include "metrics/image_metrics.h"
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"
#include "support/render_statistics.h"
#include "support/statistical_test.h"
#include "support/technique_frame.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace gib::rt {
namespace {

// A correct technique misses one of this file's two statistical tests (the unoccluded light's
// image mean under the regular and the jittered scheme) with probability 1%.
constexpr test::TestFamily kFamily(0.01, 2);

// The test floor (support/technique_frame.h) under a 1 × 0.6 light at height 1.5 facing down,
// off centre and tilted about x (the window is then not square to the image).
scene::Scene lightOverFloor() {
  scene::Scene s = test::floorScene();
  s.name = "light_over_floor";
  scene::Material light;
  light.name = "light";
  light.emission = scene::Rgb(4.0f, 3.0f, 2.0f);
  s.materials.push_back(light);
  scene::Mesh light_mesh;
  light_mesh.name = "light";
  light_mesh.material = 1;
  // Corners in an order whose normal faces down (−y, tilted).
  scene::appendQuad(light_mesh, {0.2f, 1.5f, -0.3f}, {1.2f, 1.5f, -0.3f}, {1.2f, 1.4f, 0.3f},
                    {0.2f, 1.4f, 0.3f});
  s.meshes.push_back(light_mesh);
  return s;
}

// Nothing occludes the light: the image mean agrees with the reference's by a t test on its
// standard error, allowing 0.5% for GL's pixel-centre sample against the reference's pixel-area
// average, and the per-pixel error is small. The occlusion query weighs every pixel
// of the window alike, a coarse approximation (§4.1.1): within 5%, and further off than regular.
TEST(JitteredLightSamplingTechnique, AnUnoccludedAreaLightOverAPlaneMatchesTheReference) {
  const scene::Scene scene = lightOverFloor();
  const int size = 40;
  const ref::RenderResult reference = test::renderClassReference(scene, size, 64, {0, 1});
  const test::ImageMean truth = test::imageMean(reference);
  const double m_ref = truth.mean;
  for (const char* scheme : {"scheme=regular", "scheme=jittered"}) {
    const TechniqueRunResult r =
        test::renderOneFrame(scene, "jittered_light_sampling", {scheme}, size);
    EXPECT_EQ(r.path_class, (scene::PathClass{0, 1}));
    EXPECT_TRUE(kFamily.tTest(test::imageMean(r.image), m_ref, truth.standard_error, truth.dof,
                              0.005 * m_ref))
        << scheme;
    EXPECT_LT(metrics::computeMape(reference.mean, r.image).value, 0.03) << scheme;
    EXPECT_EQ(image::countNonFinite(r.image), 0u);
  }
  const double regular = std::abs(
      test::imageMean(
          test::renderOneFrame(scene, "jittered_light_sampling", {"scheme=regular"}, size).image) -
      m_ref);
  const double query =
      std::abs(test::imageMean(test::renderOneFrame(scene, "jittered_light_sampling",
                                                    {"scheme=occlusion_query"}, size)
                                   .image) -
               m_ref);
  EXPECT_LT(query, 0.05 * m_ref);
  EXPECT_GT(query, regular);
}

// The image averaged over blocks of k × k pixels: k² pixel-centre samples per pixel of the
// smaller image, which approach the reference's pixel-area average at edges (one sample per
// pixel would differ from it at every edge by more than the shadows differ).
image::Image blockAverage(const image::Image& image, int k) {
  image::Image out(image.width() / k, image.height() / k);
  for (int y = 0; y < out.height(); ++y)
    for (int x = 0; x < out.width(); ++x)
      for (int c = 0; c < 3; ++c) {
        double sum = 0;
        for (int j = 0; j < k; ++j)
          for (int i = 0; i < k; ++i) sum += image.pixel(x * k + i, y * k + j)[c];
        out.pixel(x, y)[c] = float(sum / (k * k));
      }
  return out;
}

// Whether a pixel or one of its eight neighbours sees the light itself (radiance 17; lit walls
// stay below 1): a sliver of the light in a pixel outweighs its shadows, and pixel-centre samples
// miss slivers that the reference's pixel-area average keeps.
bool nearTheLight(const image::Image& reference, int x, int y) {
  for (int j = std::max(0, y - 1); j <= std::min(reference.height() - 1, y + 1); ++j)
    for (int i = std::max(0, x - 1); i <= std::min(reference.width() - 1, x + 1); ++i)
      if (reference.pixel(i, j)[0] >= 1.0f) return true;
  return false;
}

// relMSE off the light, less the reference's own noise: the mean of ((t − r)² − Var r) / (r² + ε)
// over pixels and channels, an unbiased estimate of the squared error against the truth (the
// reference's noise would otherwise dominate the small differences between real-time images).
double relMseLessReferenceNoise(const ref::RenderResult& reference, const image::Image& test) {
  double sum = 0;
  int n = 0;
  for (int y = 0; y < test.height(); ++y)
    for (int x = 0; x < test.width(); ++x) {
      if (nearTheLight(reference.mean, x, y)) continue;
      for (int c = 0; c < 3; ++c) {
        const double r = reference.mean.pixel(x, y)[c], d = test.pixel(x, y)[c] - r;
        sum += (d * d - reference.variance.pixel(x, y)[c]) / (r * r + metrics::kRelativeEpsilon);
        ++n;
      }
    }
  return sum / n;
}

// The Cornell box's soft shadows against the reference, each real-time image rendered at 4× the
// size and averaged down: jittered sampling with one sample per pixel of 16² coverage images is
// closer than `direct` with its default sixteen shadow-mapped samples, and four samples per pixel
// closer still. Deterministic: the reference is a fixed render (seed 0), the rest fixed samples.
TEST(JitteredLightSamplingTechnique, CornellPenumbraeBeatSixteenShadowMappedSamples) {
  const scene::Scene scene = scene::loadScene("cornell", {});
  const int size = 32, zoom = 4;
  const ref::RenderResult reference = test::renderClassReference(scene, size, 1024, {0, 1});
  auto error = [&](const std::string& technique, const std::vector<std::string>& set) {
    const image::Image fine = test::renderOneFrame(scene, technique, set, size * zoom).image;
    return relMseLessReferenceNoise(reference, blockAverage(fine, zoom));
  };
  const double direct = error("direct", {});
  const double jittered1 = error("jittered_light_sampling", {"sampling_size=16"});
  const double jittered4 =
      error("jittered_light_sampling", {"sampling_size=16", "samples_per_pixel=4"});
  std::printf("relMSE: direct %.2e, jittered1 %.2e, jittered4 %.2e\n", direct, jittered1,
              jittered4);
  EXPECT_LT(jittered1, direct);
  EXPECT_LT(jittered4, jittered1);
}

// One G-buffer draw, one emission draw, and per batch of points two coverage draws (the light,
// its occluders) and one weighing dispatch, whatever the number of points in the batch.
TEST(JitteredLightSamplingTechnique, GpuCommandsPerFrameAreThreePerBatch) {
  const scene::Scene scene = scene::loadScene("cornell", {});
  const TechniqueRunResult r = test::renderOneFrame(scene, "jittered_light_sampling", {}, 24);
  const PassRecord& frame = r.profile.passes.front();
  ASSERT_EQ(frame.gpu_commands.size(), 1u);
  EXPECT_EQ(frame.gpu_commands[0], 2 + 3);  // 576 points: one batch
}

}  // namespace
}  // namespace gib::rt
