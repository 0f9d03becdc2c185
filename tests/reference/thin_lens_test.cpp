// The thin-lens reference camera (docs/architecture.md, "Camera"; book §11.4): the ground truth
// for depth of field. Checked against the thin lens's closed forms: a point off focus images as a
// uniform disc of the thin-lens radius, the plane in focus as sharply as through the pinhole; and
// a lens of radius 0 is the pinhole, bit for bit, with the pinhole's hash and store key.
#include "reference/progressive_renderer.h"
#include "reference/reference_store.h"
#include "scene/camera.h"
#include "scene/mesh_builder.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>

namespace gib::ref {
namespace {

constexpr int kSize = 64;
constexpr float kFovDeg = 40.0f;
constexpr float kFocus = 2.0f;  // D, m

// A black world seen from the origin down −z, holding one emitter (radiance 1) facing the camera:
// the square of side `side` centred on the axis at depth `depth`, or with `half_plane` the half
// plane x < edge_x at that depth.
scene::Scene emitterScene(float depth, float side, float lens_radius) {
  scene::Scene s;
  s.name = "thin_lens_emitter";
  scene::Material lamp;
  lamp.name = "lamp";
  lamp.emission = scene::Rgb(1.0f);
  s.materials.push_back(lamp);
  scene::Mesh quad;
  quad.name = "emitter";
  const float h = 0.5f * side;
  // Wound counter-clockwise seen from +z, so that it emits towards the camera.
  scene::appendQuad(quad, {-h, -h, -depth}, {h, -h, -depth}, {h, h, -depth}, {-h, h, -depth});
  s.meshes.push_back(quad);
  s.camera.position = {0, 0, 0};
  s.camera.look_at = {0, 0, -1};
  s.camera.vertical_fov_deg = kFovDeg;
  s.camera.lens_radius = lens_radius;
  s.camera.focus_distance = kFocus;
  scene::validateScene(s);
  return s;
}

// The side (m) on the plane in focus of one pixel: the pinhole's image plane at distance D.
double pixelSizeAtFocus() {
  return 2.0 * kFocus * std::tan(glm::radians(double(kFovDeg)) * 0.5) / kSize;
}

RenderResult render(const scene::Scene& scene, PixelSampling sampling, std::uint32_t spp) {
  RenderSettings settings;
  settings.width = settings.height = kSize;
  settings.spp = spp;
  settings.replicas = 8;
  settings.pixel_sampling = sampling;
  return renderReference(scene, settings);
}

// The image's energy-weighted second moment about the image centre (px²), and its standard
// error by the delta method over the pixels' independent means (each pixel's variance from its
// replicas): M = Σ wᵢ ρᵢ² / Σ wᵢ, ∂M/∂wᵢ = (ρᵢ² − M) / Σ w.
struct Moment {
  double mean_square_radius = 0;
  double standard_error = 0;
  double energy_beyond = 0;  // fraction of the energy farther than `support` from the centre
};
Moment secondMoment(const RenderResult& r, double support) {
  double w = 0, wr2 = 0, beyond = 0;
  auto radius2 = [](int x, int y) {
    const double dx = x + 0.5 - 0.5 * kSize, dy = y + 0.5 - 0.5 * kSize;
    return dx * dx + dy * dy;
  };
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double v = r.mean.pixel(x, y)[0];
      w += v;
      wr2 += v * radius2(x, y);
      if (radius2(x, y) > support * support) beyond += v;
    }
  Moment m;
  m.mean_square_radius = wr2 / w;
  double variance = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double g = (radius2(x, y) - m.mean_square_radius) / w;
      variance += g * g * r.variance.pixel(x, y)[0];
    }
  m.standard_error = std::sqrt(variance);
  m.energy_beyond = beyond / w;
  return m;
}

// A lens of radius R focused at D images a point at depth d as a uniform disc: the ray from lens
// point ℓ (|ℓ| ≤ R) through the focus point f meets depth d at ℓ + (f − ℓ)·d/D, which is on the
// axis when f = −ℓ·(D − d)/d. So f fills a disc of world radius r = R·|d − D|/d on the focus
// plane, uniformly (ℓ is uniform on the lens), and r_px = r / (pixel size at D). The emitter's
// own image there is a square of side s·D/d, whose convolution with the disc adds its second
// moment (s·D/d)²/6, and the pixels' box adds 1/6 px² (the offset of a point in its pixel, two
// uniform coordinates of variance 1/12). A uniform disc's mean squared radius is r²/2, so
//   M = r_px²/2 + (s·D/d)²/6 + 1/6   (px²).
// Tolerance: 4 standard errors of the measured M (two-sided p ≈ 6·10⁻⁵ per case, two cases) plus
// 1 % of M for the pixel grid's cut of the disc's rim, where a pixel's offset is not uniform (the
// rim's pixels hold 2πr_px·1 px of πr_px² px², about 15 % of the energy at r_px = 13, and their
// offsets err by at most a tenth of a pixel's mean square).
TEST(ThinLens, APointOffFocusBlursToTheThinLensDisc) {
  const double pixel = pixelSizeAtFocus();
  for (const float depth : {1.0f, 4.0f}) {  // in front of the focus plane, and behind it
    // The radius giving a disc of 13 px.
    const double disc_world = 13.0 * pixel;
    const float lens_radius = float(disc_world * depth / std::abs(depth - kFocus));
    // An emitter whose pinhole image is 4 px wide: small against the disc, large enough that
    // 1024 samples per pixel hit it some 16 000 times (3 % of the disc's samples).
    const float side = float(4.0 * pixel * depth / kFocus);
    const scene::Scene scene = emitterScene(depth, side, lens_radius);
    const RenderResult r = render(scene, PixelSampling::kArea, 1024);

    const double disc_px = lens_radius * std::abs(depth - kFocus) / depth / pixel;
    const double square_px = side * kFocus / depth / pixel;
    const double expected = disc_px * disc_px / 2 + square_px * square_px / 6 + 1.0 / 6;
    // Every ray hits within the disc widened by the square's half diagonal and a pixel's.
    const Moment m = secondMoment(r, disc_px + square_px / std::sqrt(2.0) + std::sqrt(0.5));
    const double measured_radius =
        std::sqrt(2 * (m.mean_square_radius - square_px * square_px / 6 - 1.0 / 6));
    std::printf(
        "depth %.1f m, lens radius %.4f m: disc radius %.3f px expected, %.3f px "
        "measured; M %.3f ± %.3f px² (expected %.3f); energy beyond the disc %.2e\n",
        depth, lens_radius, disc_px, measured_radius, m.mean_square_radius, m.standard_error,
        expected, m.energy_beyond);
    EXPECT_NEAR(m.mean_square_radius, expected, 4 * m.standard_error + 0.01 * expected);
    EXPECT_LT(m.standard_error, 0.01 * expected) << "the measurement should be informative";
    EXPECT_EQ(m.energy_beyond, 0.0);
  }
}

// Every lens ray towards a point of the plane in focus meets the plane at that point, so a sharp
// edge on that plane renders as through the pinhole: each pixel's samples see the same side of
// the edge, but for a ray that float rounding moves across it. The edge runs through the middle
// of a pixel column, so the pinhole's edge pixels are partly covered. The same lens focused at
// twice the distance smears the edge over many columns (what the test would miss otherwise).
TEST(ThinLens, ThePlaneInFocusIsAsSharpAsThroughThePinhole) {
  constexpr std::uint32_t kSpp = 64;
  auto edgePlane = [](float lens_radius, float focus) {
    // A half plane x < 0.3 px at the focus depth, far wider than the view.
    scene::Scene s = emitterScene(kFocus, 1.0f, lens_radius);
    const float edge = float(0.3 * pixelSizeAtFocus());
    s.meshes[0].positions.clear();
    s.meshes[0].triangles.clear();
    scene::appendQuad(s.meshes[0], {-10, -10, -kFocus}, {edge, -10, -kFocus}, {edge, 10, -kFocus},
                      {-10, 10, -kFocus});
    s.camera.focus_distance = focus;
    return s;
  };
  // Columns per row whose value is strictly between the two sides.
  auto edgeWidth = [](const image::Image& image) {
    int partial = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const float v = image.pixel(x, y)[0];
        partial += v > 0.0f && v < 1.0f;
      }
    return double(partial) / kSize;
  };
  const RenderResult pinhole = render(edgePlane(0.0f, kFocus), PixelSampling::kArea, kSpp);
  const RenderResult focused = render(edgePlane(0.2f, kFocus), PixelSampling::kArea, kSpp);
  const RenderResult defocused = render(edgePlane(0.2f, 2 * kFocus), PixelSampling::kArea, kSpp);
  float max_difference = 0;
  for (std::size_t i = 0; i < pinhole.mean.data().size(); ++i)
    max_difference =
        std::max(max_difference, std::abs(pinhole.mean.data()[i] - focused.mean.data()[i]));
  std::printf(
      "edge width (columns): pinhole %.2f, focused lens %.2f, lens focused at 2D %.2f; "
      "largest pixel difference %.4f\n",
      edgeWidth(pinhole.mean), edgeWidth(focused.mean), edgeWidth(defocused.mean), max_difference);
  EXPECT_EQ(edgeWidth(pinhole.mean), 1.0);
  EXPECT_EQ(edgeWidth(focused.mean), edgeWidth(pinhole.mean));
  // At most two of a pixel's samples land across the edge by rounding.
  EXPECT_LE(max_difference, 2.0f / kSpp);
  // Focused at 2D, the plane's points blur to discs of R·|d − D|/d = 0.2 m on the plane at 2D,
  // 4.4 of its pixels: the edge spreads across about 9 columns.
  EXPECT_GT(edgeWidth(defocused.mean), 6.0);
}

bool bitIdentical(const image::Image& a, const image::Image& b) {
  return a.sameSize(b) && std::memcmp(a.data().data(), b.data().data(), a.data().size_bytes()) == 0;
}

// Radius 0 is the pinhole whatever the focus distance: the same rays (bit for bit, in both pixel
// samplings: the pixel centre's one shared ray included), the same scene hash and store key. A
// lens of radius > 0 is keyed apart, and an explicit focus at look_at's distance is the default.
TEST(ThinLens, RadiusZeroIsThePinholeBitForBit) {
  scene::Scene pinhole = emitterScene(1.0f, 0.3f, 0.0f);
  pinhole.camera.focus_distance = 0;  // the default
  scene::Scene zero = pinhole;
  zero.camera.focus_distance = 3.5f;
  EXPECT_EQ(scene::hashScene(zero), scene::hashScene(pinhole));
  ReferenceSpec spec;
  spec.scene = "thin_lens_emitter";
  EXPECT_EQ(referenceKey(zero, spec), referenceKey(pinhole, spec));
  for (const PixelSampling sampling : {PixelSampling::kArea, PixelSampling::kCenter}) {
    const RenderResult a = render(pinhole, sampling, 8);
    const RenderResult b = render(zero, sampling, 8);
    EXPECT_TRUE(bitIdentical(a.mean, b.mean)) << pixelSamplingName(sampling);
    EXPECT_TRUE(bitIdentical(a.variance, b.variance)) << pixelSamplingName(sampling);
  }
  // The frame's rays are the pinhole's for any lens sample.
  const scene::CameraFrame frame = scene::makeCameraFrame(zero.camera, 7, 5);
  const scene::CameraRay ray = scene::cameraRay(frame, 7, 5, 2.25f, 3.5f, {0.9f, 0.1f});
  const glm::vec3 direction = scene::cameraRayDirection(frame, 7, 5, 2.25f, 3.5f);
  EXPECT_EQ(std::memcmp(&ray.direction, &direction, sizeof direction), 0);
  EXPECT_EQ(ray.origin, zero.camera.position);

  scene::Scene lens = pinhole;
  lens.camera.lens_radius = 0.01f;
  EXPECT_NE(scene::hashScene(lens), scene::hashScene(pinhole));
  EXPECT_NE(referenceKey(lens, spec), referenceKey(pinhole, spec));
  scene::Scene explicit_focus = lens;
  explicit_focus.camera.focus_distance = 1.0f;  // look_at's distance
  EXPECT_EQ(scene::hashScene(explicit_focus), scene::hashScene(lens));
  explicit_focus.camera.focus_distance = 1.5f;
  EXPECT_NE(scene::hashScene(explicit_focus), scene::hashScene(lens));
}

// With pixel-centre sampling the lens still spreads the samples (each draws its own lens point):
// a defocused point is a disc, not the pinhole's single pixel.
TEST(ThinLens, PixelCentresStillSampleTheLens) {
  const double disc_px = 6.0;
  const float lens_radius = float(disc_px * pixelSizeAtFocus());  // depth 1, |d − D|/d = 1
  // An emitter whose pinhole image is 3 px wide: 9 of the disc's 113 px², so each pixel centre
  // in the disc sees it through 8 % of the lens, in some of its 64 samples but with odds 0.5 %.
  const float side = float(3.0 * pixelSizeAtFocus() / kFocus);
  const RenderResult r = render(emitterScene(1.0f, side, lens_radius), PixelSampling::kCenter, 64);
  int lit = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) lit += r.mean.pixel(x, y)[0] > 0;
  // The disc covers about π·6² ≈ 113 pixel centres; the pinhole would light about 9.
  EXPECT_GT(lit, 60);
}

TEST(ThinLens, ConcentricMapFillsTheUnitDisc) {
  EXPECT_EQ(scene::concentricDisc({0.5f, 0.5f}), glm::vec2(0.0f));
  // The square's edges go to the circle; its middle lines to the axes.
  for (const glm::vec2 u : {glm::vec2(1, 0.5f), glm::vec2(0, 0.5f), glm::vec2(0.5f, 1),
                            glm::vec2(0.5f, 0), glm::vec2(1, 1), glm::vec2(0, 0.2f)})
    EXPECT_NEAR(glm::length(scene::concentricDisc(u)), 1.0f, 1e-6f) << u.x << "," << u.y;
  EXPECT_NEAR(scene::concentricDisc({1, 0.5f}).x, 1.0f, 1e-6f);
  EXPECT_NEAR(scene::concentricDisc({0.5f, 1}).y, 1.0f, 1e-6f);
}

}  // namespace
}  // namespace gib::ref
