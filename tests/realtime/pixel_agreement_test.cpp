// The acceptance test of the GL camera and G-buffer (docs/architecture.md, "Camera": the GL
// renderers and the path tracer produce the same pixel for the same ray): albedo, normal and
// distance rendered with GL agree with Embree's primary rays through the pixel centres everywhere
// but at silhouettes, where the rasteriser's and the ray tracer's edge rules may pick different
// triangles. A control shifts the rays by half a pixel to show that the comparison can fail.
#include "realtime/gbuffer/gbuffer.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "reference/primary_agreement.h"
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"
#include "support/gl_test_context.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <string>

namespace gib::rt {
namespace {

constexpr double kMaxDisagreement = 0.005;  // silhouette pixels

struct Case {
  std::string scene;
  int width, height;
  double min_hit_fraction;  // so that agreement on empty pixels cannot pass the test alone
};

// Test names and failure messages show the case, not its bytes.
void PrintTo(const Case& c, std::ostream* os) {
  *os << c.scene << " " << c.width << "x" << c.height;
}

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
  return info.param.scene + "_" + std::to_string(info.param.width) + "x" +
         std::to_string(info.param.height);
}

struct GlPixels {
  image::Image position, normal, albedo;  // RGBA, as the G-buffer holds them
};

GlPixels renderGBuffer(const scene::Scene& scene, int width, int height) {
  const GpuScene gpu(scene, width, height);
  GBuffer gbuffer(width, height);
  gbuffer.render(gpu);
  return {gl::readTexture(gbuffer.position(), 4), gl::readTexture(gbuffer.normal(), 4),
          gl::readTexture(gbuffer.albedo(), 4)};
}

// Where GL and Embree agree on the surface, GL's albedo is that surface's material's.
std::size_t albedoMismatches(const scene::Scene& scene, const GlPixels& gl,
                             const image::Image& disagreement) {
  std::size_t mismatches = 0;
  for (int y = 0; y < gl.normal.height(); ++y)
    for (int x = 0; x < gl.normal.width(); ++x) {
      if (disagreement.pixel(x, y)[0] != 0 || gl.position.pixel(x, y)[3] < 0) continue;
      const scene::Rgb diffuse = scene.materials[std::size_t(gl.normal.pixel(x, y)[3])].diffuse;
      for (int k = 0; k < 3; ++k)
        mismatches += std::abs(gl.albedo.pixel(x, y)[k] - diffuse[k]) > 1e-5f;
    }
  return mismatches;
}

class PixelAgreementTest : public test::GlTest, public ::testing::WithParamInterface<Case> {};

TEST_P(PixelAgreementTest, GlAndEmbreeAgreeButAtSilhouettes) {
  const Case& c = GetParam();
  const scene::Scene scene = scene::loadScene(c.scene);
  const GlPixels gl = renderGBuffer(scene, c.width, c.height);
  const ref::PrimaryAgreement tally = ref::comparePrimarySurfaces(scene, gl.position, gl.normal);
  std::cout << c.scene << " " << c.width << "×" << c.height << ": " << tally.disagreements << " of "
            << tally.pixels << " pixels disagree (" << 100.0 * tally.disagreementFraction()
            << " %), " << 100.0 * double(tally.hits) / double(tally.pixels) << " % hit a surface\n";
  EXPECT_GE(double(tally.hits) / double(tally.pixels), c.min_hit_fraction);
  EXPECT_LT(tally.disagreementFraction(), kMaxDisagreement);
  EXPECT_EQ(albedoMismatches(scene, gl, tally.mask), 0u);
}

TEST_P(PixelAgreementTest, HalfAPixelOffDisagreesClearly) {
  const Case& c = GetParam();
  const scene::Scene scene = scene::loadScene(c.scene);
  const GlPixels gl = renderGBuffer(scene, c.width, c.height);
  for (const auto& [dx, dy] : {std::pair{1.0f, 0.5f}, std::pair{0.5f, 1.0f}}) {
    const ref::PrimaryAgreement tally =
        ref::comparePrimarySurfaces(scene, gl.position, gl.normal, {dx, dy});
    std::cout << c.scene << " " << c.width << "×" << c.height << ", rays through (x+" << dx
              << ", y+" << dy << "): " << 100.0 * tally.disagreementFraction() << " % disagree\n";
    EXPECT_GT(tally.disagreementFraction(), 10 * kMaxDisagreement) << dx << ", " << dy;
  }
}

// The emission a surface seen at G-buffer pixel (x, y) sends towards the eye: emission is
// one-sided (front side only), and the G-buffer's normal is the triangle's front.
scene::Rgb emissionSeen(const scene::Scene& scene, const GlPixels& gl, int x, int y) {
  const float* position = gl.position.pixel(x, y);
  if (position[3] < 0) return scene::Rgb(0.0f);
  const float* normal = gl.normal.pixel(x, y);
  const glm::vec3 to_eye = scene.camera.position - glm::vec3(position[0], position[1], position[2]);
  if (glm::dot(glm::vec3(normal[0], normal[1], normal[2]), to_eye) <= 0) return scene::Rgb(0.0f);
  return scene.materials[std::size_t(normal[3])].emission;
}

struct EmissionComparison {
  std::size_t compared = 0, emissive = 0, mismatches = 0;
};

// Compares the emission-only reference (LE: paths of no bounce) with the emission of the surface
// GL sees, at every pixel where the two agree on that surface.
EmissionComparison compareEmission(const scene::Scene& scene, const GlPixels& gl,
                                   const image::Image& disagreement, ref::PixelSampling sampling) {
  ref::RenderSettings settings;
  settings.width = gl.position.width();
  settings.height = gl.position.height();
  settings.spp = 4;
  settings.path_class = scene::PathClass{0, 0};
  settings.pixel_sampling = sampling;
  const image::Image reference = ref::renderReference(scene, settings).mean;
  EmissionComparison result;
  for (int y = 0; y < settings.height; ++y)
    for (int x = 0; x < settings.width; ++x) {
      if (disagreement.pixel(x, y)[0] != 0) continue;
      const scene::Rgb expected = emissionSeen(scene, gl, x, y);
      ++result.compared;
      result.emissive += expected.r > 0;
      bool equal = true;
      for (int k = 0; k < 3; ++k)
        equal = equal && std::abs(reference.pixel(x, y)[k] - expected[k]) <= 1e-6f * expected[k];
      result.mismatches += !equal;
    }
  return result;
}

INSTANTIATE_TEST_SUITE_P(Scenes, PixelAgreementTest,
                         ::testing::Values(Case{"cornell", 256, 256, 0.9},
                                           Case{"cornell", 320, 200, 0.5},
                                           Case{"chamber", 256, 192, 0.9}),
                         caseName);

// A pixel-centre reference traces the G-buffer's own ray: its emission-only image is, at every
// pixel outside the disagreement mask, exactly the emission of the surface the rasteriser saw.
// The box-filtered reference averages over the pixel, so it differs on the emitters' edges. On
// the Cornell box, whose light is in view (the chamber's lights are not, and the test above
// covers its rays).
class PixelCentreReferenceTest : public test::GlTest {};

TEST_F(PixelCentreReferenceTest, SeesTheGBuffersSurfaceOutsideTheMask) {
  const scene::Scene scene = scene::loadScene("cornell");
  for (const auto& [width, height] : {std::pair{256, 256}, std::pair{320, 200}}) {
    const GlPixels gl = renderGBuffer(scene, width, height);
    const ref::PrimaryAgreement agreement =
        ref::comparePrimarySurfaces(scene, gl.position, gl.normal);
    const EmissionComparison centre =
        compareEmission(scene, gl, agreement.mask, ref::PixelSampling::kCenter);
    std::cout << width << "×" << height << ": " << centre.compared << " pixels compared ("
              << centre.emissive << " on the light), " << agreement.disagreements << " masked\n";
    EXPECT_GT(centre.emissive, 0u) << "no emitter in view: the comparison would be of zeros";
    EXPECT_EQ(centre.mismatches, 0u);
    const EmissionComparison area =
        compareEmission(scene, gl, agreement.mask, ref::PixelSampling::kArea);
    EXPECT_GT(area.mismatches, 0u) << "the box filter should blur the light's edges";
  }
}

}  // namespace
}  // namespace gib::rt
