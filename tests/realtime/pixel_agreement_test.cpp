// The acceptance test of the GL camera and G-buffer (docs/architecture.md, "Camera": the GL
// renderers and the path tracer produce the same pixel for the same ray): albedo, normal and
// distance rendered with GL agree with Embree's primary rays through the pixel centres everywhere
// but at silhouettes, where the rasteriser's and the ray tracer's edge rules may pick different
// triangles. A control shifts the rays by half a pixel to show that the comparison can fail.
#include "realtime/gbuffer/gbuffer.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "reference/embree_scene.h"
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

constexpr double kMaxDisagreement = 0.005;   // silhouette pixels
constexpr float kDistanceTolerance = 1e-3f;  // relative
constexpr float kNormalTolerance = 0.999f;   // cosine
constexpr float kAlbedoTolerance = 1e-5f;

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

bool agrees(const scene::Scene& scene, const ref::Hit& hit, const float* position,
            const float* normal, const float* albedo) {
  const bool gl_hit = position[3] >= 0;
  if (!gl_hit || !hit.valid()) return gl_hit == hit.valid();
  if (std::abs(position[3] - hit.t) > kDistanceTolerance * hit.t) return false;
  const scene::Mesh& mesh = scene.meshes[hit.mesh];
  const glm::uvec3 t = mesh.triangles[hit.triangle];
  const glm::vec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
  const glm::vec3 expected_normal = glm::normalize(glm::cross(b - a, c - a));
  if (glm::dot(expected_normal, glm::vec3(normal[0], normal[1], normal[2])) < kNormalTolerance)
    return false;
  if (normal[3] != float(mesh.material)) return false;
  const scene::Rgb diffuse = scene.materials[mesh.material].diffuse;
  for (int k = 0; k < 3; ++k)
    if (std::abs(albedo[k] - diffuse[k]) > kAlbedoTolerance) return false;
  return true;
}

struct Tally {
  std::size_t pixels = 0, hits = 0, disagreements = 0;
  double disagreementFraction() const { return double(disagreements) / double(pixels); }
  double hitFraction() const { return double(hits) / double(pixels); }
};

// Compares GL's pixel (x, y) with Embree's ray through the image point (x + dx, y + dy).
Tally compare(const scene::Scene& scene, const GlPixels& gl, float dx, float dy) {
  const ref::EmbreeScene embree(scene);
  const int width = gl.position.width(), height = gl.position.height();
  const scene::CameraFrame frame = scene::makeCameraFrame(scene.camera, width, height);
  Tally tally;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::vec3 direction =
          scene::cameraRayDirection(frame, width, height, float(x) + dx, float(y) + dy);
      const ref::Hit hit = embree.intersect(frame.origin, direction);
      ++tally.pixels;
      tally.hits += hit.valid();
      tally.disagreements += !agrees(scene, hit, gl.position.pixel(x, y), gl.normal.pixel(x, y),
                                     gl.albedo.pixel(x, y));
    }
  return tally;
}

class PixelAgreementTest : public test::GlTest, public ::testing::WithParamInterface<Case> {};

TEST_P(PixelAgreementTest, GlAndEmbreeAgreeButAtSilhouettes) {
  const Case& c = GetParam();
  const scene::Scene scene = scene::loadScene(c.scene);
  const Tally tally = compare(scene, renderGBuffer(scene, c.width, c.height), 0.5f, 0.5f);
  std::cout << c.scene << " " << c.width << "×" << c.height << ": " << tally.disagreements << " of "
            << tally.pixels << " pixels disagree (" << 100.0 * tally.disagreementFraction()
            << " %), " << 100.0 * tally.hitFraction() << " % hit a surface\n";
  EXPECT_GE(tally.hitFraction(), c.min_hit_fraction);
  EXPECT_LT(tally.disagreementFraction(), kMaxDisagreement);
}

TEST_P(PixelAgreementTest, HalfAPixelOffDisagreesClearly) {
  const Case& c = GetParam();
  const scene::Scene scene = scene::loadScene(c.scene);
  const GlPixels gl = renderGBuffer(scene, c.width, c.height);
  for (const auto& [dx, dy] : {std::pair{1.0f, 0.5f}, std::pair{0.5f, 1.0f}}) {
    const Tally tally = compare(scene, gl, dx, dy);
    std::cout << c.scene << " " << c.width << "×" << c.height << ", rays through (x+" << dx
              << ", y+" << dy << "): " << 100.0 * tally.disagreementFraction() << " % disagree\n";
    EXPECT_GT(tally.disagreementFraction(), 10 * kMaxDisagreement) << dx << ", " << dy;
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, PixelAgreementTest,
                         ::testing::Values(Case{"cornell", 256, 256, 0.9},
                                           Case{"cornell", 320, 200, 0.5},
                                           Case{"chamber", 256, 192, 0.9}),
                         caseName);

}  // namespace
}  // namespace gib::rt
