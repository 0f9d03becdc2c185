// One bounce gathered by rasterization (Fournier & Péroche §5): the gather views' weights against
// closed forms (a uniform background; a square patch's form factor by Lambert's formula), and the
// technique against the reference restricted to two bounces.
#include "realtime/techniques/hemispherical_gather/hemisphere_gather.h"

#include "metrics/image_metrics.h"
#include "realtime/atlas/atlas_layout.h"
#include "realtime/technique_runner.h"
#include "realtime/techniques/hemispherical_gather/hemispherical_gather_shared.h"
#include "realtime/techniques/hemispherical_gather/hemispherical_gather_technique.h"
#include "realtime/techniques/hemispherical_gather/voxel_slices.h"
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"
#include "support/form_factor.h"
#include "support/gl_memory.h"
#include "support/gl_test_context.h"
#include "support/render_statistics.h"
#include "support/technique_frame.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace gib::rt {
namespace {

constexpr double kPi = std::numbers::pi;
// The scene extent the gather tests give HemisphereGather: its views are drawn from each point
// lifted 10⁻⁴ of it along the normal (hemisphere_gather.cpp), which moves the patch's form factor
// by ~0.2% at height 1, so the patch test's points are lifted as well.
constexpr float kExtent = 10.0f;
constexpr double kLift = 1e-4 * kExtent;

// A 4 × 4 floor seen from above at an angle, and optionally a 1 × 1 patch at height 1 over its
// centre, facing down.
scene::Scene floorScene(bool patch) {
  scene::Scene s;
  s.name = "gather_floor";
  s.camera.position = {0.0f, 2.5f, 2.5f};
  s.camera.look_at = {0.0f, 0.0f, 0.0f};
  s.camera.vertical_fov_deg = 45.0f;
  scene::Material grey;
  grey.name = "grey";
  grey.diffuse = scene::Rgb(0.5f);
  s.materials = {grey};
  scene::Mesh floor;
  floor.name = "floor";
  scene::appendQuad(floor, {-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2});
  s.meshes = {floor};
  return patch ? test::withUnitPatch(s) : s;
}

const std::vector<glm::dvec3>& kPatch = test::unitPatchCorners();

struct Gathered {
  image::Image irradiance;  // the grid
  image::Image position;    // the G-buffer, for each point's place
  int spacing = 0;
};

// Gathers at every 8th pixel of a 64² view of `scene` with a radiance atlas of 1 everywhere.
Gathered gatherUnitRadiance(const scene::Scene& scene, int projection, int view_size,
                            const glm::vec3& background) {
  const int size = 64, spacing = 8;
  GpuScene gpu(scene, size, size);
  GBuffer gbuffer(size, size);
  gbuffer.render(gpu);
  const std::vector<atlas::AtlasTriangle> triangles = atlas::atlasTriangles(scene);
  const atlas::AtlasLayout layout = atlas::layoutAtlas(triangles, 64);
  const atlas::AtlasMesh mesh(triangles, layout, 3);
  gl::Texture radiance = gl::Texture::make2D(GL_RGBA32F, 64, 64);
  const float one[4] = {1, 1, 1, 1};
  glClearTexImage(radiance.id(), 0, GL_RGBA, GL_FLOAT, one);
  HemisphereGather gather(projection, view_size, spacing, size, size, kExtent);
  gl::PassProfiler unmeasured;  // outside a frame: no timing
  gather.gather(gpu, mesh, radiance, gbuffer, unmeasured, background);
  return {gl::readTexture(gather.irradiance(), 3), gl::readTexture(gbuffer.position(), 4), spacing};
}

// The views' weights and their float sums, as gather_sum.comp.glsl forms them, for the closed
// forms to be met within the sums' rounding and the pixels' own discretisation.

// A 2⁻²⁴ float rounding, and the relative error of a view's float sum: each of the work group's
// 64 lanes adds size²/64 terms in turn, then 6 halvings add the lanes' sums, and each term comes
// from about 10 rounded operations. For positive terms Higham's bound γ_n = n·u (n the roundings
// any one term goes through) bounds the sum's relative error: 1 040 u = 6.2·10⁻⁵ at 256², 80 u =
// 4.8·10⁻⁶ at 64²; a weight 0.5% off is 80 times the larger. The perspective view's tangent is
// the shared header's literal on both sides, not each driver's tan().
constexpr double kUnitRoundoff = 0x1p-24;
double viewSumRounding(int view_size) {
  const int additions = view_size * view_size / gpu::kGatherSumGroupSize +
                        int(std::log2(double(gpu::kGatherSumGroupSize)));
  return (additions + 10) * kUnitRoundoff;
}

// The tangent the views are drawn and summed with (the shared header's literal).
double perspectiveTangent() {
  return double(gpu::kPerspectiveHalfTangent);
}

// That literal is tan(½ · 160°), to the float nearest it.
TEST(HemisphericalGatherTechnique, ThePerspectiveViewsTangentIsItsFieldOfViews) {
  EXPECT_EQ(gpu::kPerspectiveHalfTangent,
            float(std::tan(0.5 * double(gpu::kPerspectiveFieldOfViewDegrees) * kPi / 180.0)));
}

// The centre of pixel (i, j) of a size² view, in its [−1, 1]².
glm::dvec2 pixelCentre(int i, int j, int size) {
  return (glm::dvec2(i, j) + 0.5) * (2.0 / size) - 1.0;
}

// The perspective view's weight of the pixel centred at xy: its area A on the image plane at unit
// distance over r⁴.
double perspectiveWeight(const glm::dvec2& xy, int size) {
  const double tangent = perspectiveTangent(), side = 2.0 * tangent / size;
  const double r2 = 1.0 + tangent * tangent * glm::dot(xy, xy);
  return side * side / (r2 * r2);
}

// The fish-eye view's weight of each pixel whose centre lies in the unit disk: π over their count.
double fishEyeWeight(int size) {
  int count = 0;
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i)
      count += glm::dot(pixelCentre(i, j, size), pixelCentre(i, j, size)) < 1.0;
  return kPi / count;
}

class HemisphericalGather : public test::GlTest {};

// Nothing above the floor and a background of radiance L: the fish-eye view's pixels weigh π in
// all (Nusselt's analogue), so E = π·L; the 160° perspective view's weights A/r⁴ sum to
// 4 sin 80° · atan(sin 80°) = 3.0642 (the grazing 10° it leaves out), so E = 3.0642·L. Both
// within their float sums' rounding; the perspective's pixel weights, each the integrand at the
// pixel's centre, also differ from the integral by the midpoint rule's error, which their sum in
// double precision shows (4·10⁻⁷ of it at 256²).
TEST_F(HemisphericalGather, AUniformBackgroundGivesTheProjectionsCosineWeightedSolidAngle) {
  const glm::vec3 L(1.0f, 2.0f, 0.5f);
  const double sin80 = std::sin(80.0 * kPi / 180.0);
  const double perspective = 4 * sin80 * std::atan(sin80);
  const int perspective_size = 256;
  double midpoint = 0;
  for (int j = 0; j < perspective_size; ++j)
    for (int i = 0; i < perspective_size; ++i)
      midpoint += perspectiveWeight(pixelCentre(i, j, perspective_size), perspective_size);
  for (const auto& [projection, size, expected, discretisation] :
       {std::tuple{gpu::kProjectionHemispherical, 64, kPi, 0.0},
        std::tuple{gpu::kProjectionPerspective, perspective_size, perspective,
                   std::abs(midpoint - perspective)}}) {
    const Gathered g = gatherUnitRadiance(floorScene(false), projection, size, L);
    for (int y = 0; y < g.irradiance.height(); ++y)
      for (int x = 0; x < g.irradiance.width(); ++x)
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(g.irradiance.pixel(x, y)[c], expected * L[c],
                      (discretisation + viewSumRounding(size) * expected) * L[c])
              << "projection " << projection << " point " << x << "," << y;
  }
}

// The patch as a view from `origin` on the floor draws it: its outline, the
// corners and, for the fish-eye, the vertices its edges are split at (8 segments each:
// gatherUnitRadiance's 3 levels of midpoints), projected as gather_view.vert.glsl does (the
// perspective onto the image plane at 1/tan 80°, the fish-eye to the unit direction's tangent
// coordinates); and how far, in pixels of a size² view, the true outline strays from those
// straight edges (the fish-eye bends them). The view's frame is x, −z along the floor; the mirror
// image (x, z) sums the same, since the pixel grid and the weights are symmetric.
struct Outline {
  std::vector<glm::dvec2> vertices;
  double bend = 0;
};

double segmentDistance(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
  const glm::dvec2 ab = b - a;
  const double t = std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-300), 0.0, 1.0);
  return glm::length(p - (a + t * ab));
}

Outline patchOutline(const glm::dvec3& origin, int projection, int size) {
  const bool perspective = projection == gpu::kProjectionPerspective;
  auto project = [&](const glm::dvec3& p) {
    const glm::dvec3 d = p - origin;
    return perspective ? glm::dvec2(d.x, d.z) / (d.y * perspectiveTangent())
                       : glm::dvec2(d.x, d.z) / glm::length(d);
  };
  const int segments = perspective ? 1 : 8, probes = 8;
  Outline o;
  for (std::size_t c = 0; c < kPatch.size(); ++c) {
    const glm::dvec3 &from = kPatch[c], &to = kPatch[(c + 1) % kPatch.size()];
    for (int k = 0; k < segments; ++k) {
      const double t0 = double(k) / segments, t1 = double(k + 1) / segments;
      const glm::dvec2 a = project(glm::mix(from, to, t0)), b = project(glm::mix(from, to, t1));
      o.vertices.push_back(a);
      for (int m = 1; m < probes; ++m)
        o.bend = std::max(
            o.bend,
            segmentDistance(project(glm::mix(from, to, t0 + (t1 - t0) * m / probes)), a, b));
    }
  }
  o.bend *= 0.5 * size;
  return o;
}

// What a size² view of radiance 1 inside `outline` and 0 elsewhere sums to: the weights of the
// pixels whose centres the polygon holds (what the rasterizer fills), and of those whose centres
// lie within `band` pixels of it, the pixels whose share of the patch that sum may get wrong.
struct Coverage {
  double sum = 0, uncertain = 0;
};
Coverage coverage(const std::vector<glm::dvec2>& outline, int projection, int size, double band) {
  const double fish_eye_weight = fishEyeWeight(size), band_ndc = band * 2.0 / size;
  // Only the pixels around the outline's bounding box can be covered or near it.
  glm::dvec2 low(1.0), high(-1.0);
  for (const glm::dvec2& v : outline) {
    low = glm::min(low, v - band_ndc);
    high = glm::max(high, v + band_ndc);
  }
  auto pixelIndex = [&](double ndc) {
    return std::clamp(int((ndc + 1.0) * 0.5 * size), 0, size - 1);
  };
  Coverage c;
  for (int j = pixelIndex(low.y); j <= pixelIndex(high.y); ++j)
    for (int i = pixelIndex(low.x); i <= pixelIndex(high.x); ++i) {
      const glm::dvec2 xy = pixelCentre(i, j, size);
      bool inside = false;
      double distance = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < outline.size(); ++k) {
        const glm::dvec2 &a = outline[k], &b = outline[(k + 1) % outline.size()];
        if ((a.y > xy.y) != (b.y > xy.y) && xy.x < a.x + (xy.y - a.y) * (b.x - a.x) / (b.y - a.y))
          inside = !inside;
        distance = std::min(distance, segmentDistance(xy, a, b));
      }
      const double w =
          projection == gpu::kProjectionPerspective ? perspectiveWeight(xy, size) : fish_eye_weight;
      if (inside) c.sum += w;
      if (distance <= band_ndc) c.uncertain += w;
    }
  return c;
}

// A square patch of radiance 1 over the floor, for the fish-eye view at 64² and the perspective
// view at 256² where the patch lies inside its 160°. At each floor point the gathered irradiance
// is what the view's pixels hold: the weights of those whose centres the patch's drawn outline
// covers, within the float sum's rounding and the weights of the pixels whose centres lie within
// a subpixel step of the outline (the rasterizer snaps vertices to its grid of GL_SUBPIXEL_BITS;
// float's projection errs by ~10⁻⁴ pixel). That sum is π times the point-to-patch
// form factor (Lambert's formula, support/form_factor.h) but for the pixels the true outline
// crosses (within half a diagonal, plus how far the fish-eye's straight edges stray from it) and
// the weights' own discretisation: the perspective pixel's centre value against its integral,
// (h²/24)·|∇²w|/w, about h²/3 at most for w = 1/(1 + ρ²)² and side h on the image plane; the
// fish-eye's π over the pixel count against each pixel's true share, its area.
TEST_F(HemisphericalGather, APatchsIrradianceIsItsFormFactorTimesPi) {
  GLint subpixel_bits = 0;
  glGetIntegerv(GL_SUBPIXEL_BITS, &subpixel_bits);
  const double snap = std::ldexp(1.0, -subpixel_bits) + 1e-3;
  for (const auto& [projection, size] : {std::pair{gpu::kProjectionHemispherical, 64},
                                         std::pair{gpu::kProjectionPerspective, 256}}) {
    const Gathered g = gatherUnitRadiance(floorScene(true), projection, size, glm::vec3(0.0f));
    const double side = 2.0 * perspectiveTangent() / size;
    const double weight_discretisation =
        projection == gpu::kProjectionPerspective
            ? side * side / 3
            : std::abs(fishEyeWeight(size) / std::pow(2.0 / size, 2) - 1);
    int checked = 0;
    double sum_error = 0, sum_expected = 0;
    for (int y = 0; y < g.irradiance.height(); ++y)
      for (int x = 0; x < g.irradiance.width(); ++x) {
        // Both images come back with rows from the top; the grid's cells and the gather pixels
        // count GL rows, from the bottom.
        const int cell_row = g.irradiance.height() - 1 - y;
        const int px = x * g.spacing + g.spacing / 2;
        const int py = g.position.height() - 1 - (cell_row * g.spacing + g.spacing / 2);
        const float* p = g.position.pixel(px, py);
        if (p[3] < 0 || std::abs(p[1]) > 1e-3f) continue;  // not on the floor
        const glm::dvec3 point(p[0], double(p[1]) + kLift, p[2]);
        bool inside_view = true;
        for (const glm::dvec3& corner : kPatch)
          inside_view &= glm::normalize(corner - point).y > std::cos(80.0 * kPi / 180.0);
        if (projection == gpu::kProjectionPerspective && !inside_view) continue;
        const Outline outline = patchOutline(point, projection, size);
        const Coverage drawn = coverage(outline.vertices, projection, size, snap);
        const Coverage crossed =
            coverage(outline.vertices, projection, size, std::sqrt(0.5) + outline.bend);
        const double gathered = g.irradiance.pixel(x, y)[0];
        EXPECT_NEAR(gathered, drawn.sum, drawn.uncertain + viewSumRounding(size) * drawn.sum)
            << "projection " << projection << " at " << point.x << "," << point.z;
        const double expected = kPi * test::pointToPolygonFormFactor(point, {0, 1, 0}, kPatch);
        EXPECT_NEAR(drawn.sum, expected, crossed.uncertain + weight_discretisation * drawn.sum)
            << "projection " << projection << " at " << point.x << "," << point.z;
        sum_error += gathered - expected;
        sum_expected += expected;
        ++checked;
      }
    std::printf("projection %d: %d points, mean error against the form factor %.3f%%\n", projection,
                checked, 100 * sum_error / sum_expected);
    EXPECT_GE(checked, 20) << "projection " << projection;
  }
}

// On the Cornell box against the reference restricted to two bounces, each projection's image (the
// voxel slices' too: 64 slabs of 64² per axis, the box's near geometry drawn) is less than half as
// far (relMSE) as `direct`'s, which leaves the bounce out, and its path class is LE|LDE|LDDE.
// The reference is a fixed render (seed 0), so this is deterministic.
TEST(HemisphericalGatherTechnique, OneGatheredBounceHalvesTheErrorOfDirectLightAlone) {
  const scene::Scene scene = scene::loadScene("cornell", {});
  const int size = 48;
  const ref::RenderResult reference = test::renderClassReference(scene, size, 256, {0, 2});
  const double direct =
      metrics::computeRelMse(reference.mean, test::renderOneFrame(scene, "direct", {}, size).image)
          .value;
  for (const char* projection :
       {"projection=hemispherical", "projection=perspective", "projection=voxel_slices"}) {
    const TechniqueRunResult r =
        test::renderOneFrame(scene, "hemispherical_gather", {projection, "gather_spacing=4"}, size);
    EXPECT_EQ(r.path_class, (scene::PathClass{0, 2}));
    const double gathered = metrics::computeRelMse(reference.mean, r.image).value;
    std::printf("%s: relMSE %.4f, direct alone %.4f\n", projection, gathered, direct);
    EXPECT_LT(gathered, 0.5 * direct) << projection;
  }
}

// The furnace (walls of albedo ρ = 0.5 emitting 0.5): the direct light reflected once is ρ·0.5 =
// 0.25 everywhere, and its bounce ρ·0.25 = 0.125, of which the perspective view's 160° gathers
// 3.0642/π (the uniform background test's figure), 2.5% less. The bounce alone is the frame less
// `direct`'s, which draws the same emission and direct light from the same light samples (their
// direct light, 16 samples, is 1.3% over 0.25 here and cancels). Being uniform, 4 gather points
// give it. The perspective and fish-eye views' bounces lie within 1% of their shares, which tells
// the perspective view's 2.5% apart: the atlas they gather holds that direct light at every texel,
// exact over a closed surface only in expectation (the perspective view, which keeps straight edges
// straight, gathers 0.04% over its share), and the fish-eye's straight edges lose light near the
// horizon, 0.6% at tessellation level 4 (2.3% at level 1). The voxel slices lose 6%: each slab
// holds the first surface met going into it, which misses surfaces grazing the slice planes
// (README, known failure cases); held to 10%, they show that the slices beyond the near box are
// traced and hold the atlas's radiance.
TEST(HemisphericalGatherTechnique, TheFurnaceGathersItsSecondBounce) {
  const scene::Scene scene = scene::loadScene("furnace", {});
  const int size = 32;
  const double sin80 = std::sin(80.0 * kPi / 180.0);
  const double bounce = 0.125;
  const double direct = test::imageMean(test::renderOneFrame(scene, "direct", {}, size).image);
  for (const auto& [projection, tessellation, share, tolerance] :
       {std::tuple{"projection=perspective", "tessellation=0", 4 * sin80 * std::atan(sin80) / kPi,
                   0.01},
        std::tuple{"projection=hemispherical", "tessellation=4", 1.0, 0.01},
        std::tuple{"projection=voxel_slices", "tessellation=1", 1.0, 0.1}}) {
    const double gathered =
        test::imageMean(test::renderOneFrame(scene, "hemispherical_gather",
                                             {projection, tessellation, "gather_spacing=16"}, size)
                            .image) -
        direct;
    std::printf("%s: bounce %.5f, %.4f of its share\n", projection, gathered,
                gathered / (bounce * share));
    EXPECT_NEAR(gathered, bounce * share, tolerance * bounce * share) << projection;
  }
}

// The slices hold what the paper sized, 6 faces × 64 slabs × 64² texels × 16 bytes = 25.2 MB, as
// GL reports the faces' texture (its extent and component sizes, not VoxelSlices' own formula),
// and the technique's voxel_slices_mb statistic at those slices reports what GL allocated.
TEST_F(HemisphericalGather, VoxelSlicesTakeThePapersMemory) {
  const int slices = 64, size = 64;
  const scene::Scene scene = scene::loadScene("cornell", {});
  const GpuScene gpu(scene, 16, 16);
  const std::vector<atlas::AtlasTriangle> triangles = atlas::atlasTriangles(scene);
  const atlas::AtlasMesh mesh(triangles, atlas::layoutAtlas(triangles, 64), 0);
  const gl::Texture radiance = gl::Texture::make2D(GL_RGBA32F, 64, 64);
  const VoxelSlices voxels(gpu, mesh, radiance, slices, size);
  const std::int64_t allocated = test::allocatedTextureBytes(voxels.faces());
  EXPECT_EQ(allocated, std::int64_t(6) * slices * size * size * 16);
  EXPECT_EQ(std::int64_t(voxels.bytes()), allocated);

  const TechniqueInfo& info = findTechnique("hemispherical_gather");
  HemisphericalGatherTechnique technique(
      parseParameters(info.parameters,
                      {"projection=voxel_slices", "slices=" + std::to_string(slices),
                       "slice_size=" + std::to_string(size)},
                      info.name));
  technique.prepare(gpu, 16, 16);
  EXPECT_DOUBLE_EQ(test::statisticNamed(technique.statistics(), "voxel_slices_mb"),
                   double(allocated) / 1e6);
}

}  // namespace
}  // namespace gib::rt
