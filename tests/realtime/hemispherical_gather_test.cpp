// One bounce gathered by rasterization (Fournier & Péroche §5): the gather views' weights against
// closed forms (a uniform background; a square patch's form factor by Lambert's formula), and the
// technique against the reference restricted to two bounces.
#include "realtime/techniques/hemispherical_gather/hemisphere_gather.h"

#include "metrics/image_metrics.h"
#include "realtime/atlas/atlas_layout.h"
#include "realtime/technique_runner.h"
#include "realtime/techniques/hemispherical_gather/hemispherical_gather_shared.h"
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"
#include "support/form_factor.h"
#include "support/gl_test_context.h"
#include "support/technique_frame.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace gib::rt {
namespace {

constexpr double kPi = std::numbers::pi;

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
  HemisphereGather gather(projection, view_size, spacing, size, size, 10.0f);
  gl::PassProfiler unmeasured;  // outside a frame: no timing
  gather.gather(gpu, mesh, radiance, gbuffer, unmeasured, background);
  return {gl::readTexture(gather.irradiance(), 3), gl::readTexture(gbuffer.position(), 4), spacing};
}

class HemisphericalGather : public test::GlTest {};

// Nothing above the floor and a background of radiance L: the fish-eye view's pixels weigh π in
// all (Nusselt's analogue), so E = π·L; the 160° perspective view's weights A/r⁴ sum to
// 4 sin 80° · atan(sin 80°) = 3.0642 (the grazing 10° it leaves out), so E = 3.0642·L.
TEST_F(HemisphericalGather, AUniformBackgroundGivesTheProjectionsCosineWeightedSolidAngle) {
  const glm::vec3 L(1.0f, 2.0f, 0.5f);
  const double sin80 = std::sin(80.0 * kPi / 180.0);
  const double perspective = 4 * sin80 * std::atan(sin80);
  for (const auto& [projection, size, expected] :
       {std::tuple{gpu::kProjectionHemispherical, 64, kPi},
        std::tuple{gpu::kProjectionPerspective, 256, perspective}}) {
    const Gathered g = gatherUnitRadiance(floorScene(false), projection, size, L);
    for (int y = 0; y < g.irradiance.height(); ++y)
      for (int x = 0; x < g.irradiance.width(); ++x)
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(g.irradiance.pixel(x, y)[c], expected * L[c], 2e-3 * expected * L[c])
              << "projection " << projection << " point " << x << "," << y;
  }
}

// A square patch of radiance 1 over the floor: the irradiance at each floor point is π times the
// point-to-patch form factor (Lambert's formula, support/form_factor.h), for the fish-eye view at
// 64² and the perspective view at 256² where the patch lies inside its 160°. Each point within
// 10% (the pixels along the patch's edges: at 64² a far patch covers a few dozen of the disk's
// ~3 200), and the error summed over the points within 2% of the sum (when this was written:
// 0.005% fish-eye, 0.4% perspective), since edge pixels err both ways.
TEST_F(HemisphericalGather, APatchsIrradianceIsItsFormFactorTimesPi) {
  for (const auto& [projection, size] : {std::pair{gpu::kProjectionHemispherical, 64},
                                         std::pair{gpu::kProjectionPerspective, 256}}) {
    const Gathered g = gatherUnitRadiance(floorScene(true), projection, size, glm::vec3(0.0f));
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
        const glm::dvec3 point(p[0], 0.0, p[2]);
        bool inside_view = true;
        for (const glm::dvec3& corner : kPatch)
          inside_view &= glm::normalize(corner - point).y > std::cos(80.0 * kPi / 180.0);
        if (projection == gpu::kProjectionPerspective && !inside_view) continue;
        const double expected = kPi * test::pointToPolygonFormFactor(point, {0, 1, 0}, kPatch);
        const double error = g.irradiance.pixel(x, y)[0] - expected;
        EXPECT_LT(std::abs(error), 0.1 * expected + 1e-3)
            << "projection " << projection << " at " << point.x << "," << point.z;
        sum_error += error;
        sum_expected += expected;
        ++checked;
      }
    std::printf("projection %d: %d points, mean error %.3f%%\n", projection, checked,
                100 * sum_error / sum_expected);
    EXPECT_GE(checked, 20) << "projection " << projection;
    EXPECT_LT(std::abs(sum_error), 0.02 * sum_expected) << "projection " << projection;
  }
}

// On the Cornell box against the reference restricted to two bounces, each projection's image (the
// voxel slices' too: 64 slabs of 64² per axis, the box's near geometry drawn) is less than half as
// far (relMSE) as `direct`'s, which leaves the bounce out, and its path class is LE + LDE + LDDE.
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

// The furnace (walls of albedo 0.5 emitting 0.5): up to two bounces L = 0.5 + 0.25 + 0.125 =
// 0.875 at every pixel; the perspective view's 160° gathers 3.0642/π of the bounce (the uniform
// background test's figure). The voxel slices must leave no hole in the fish-eye view where the
// near geometry hands over to the slices. Within 1%: the direct part is 16 shadow-mapped light
// samples over the sphere's thousand emitting triangles.
TEST(HemisphericalGatherTechnique, TheFurnaceGathersItsSecondBounce) {
  const scene::Scene scene = scene::loadScene("furnace", {});
  const double sin80 = std::sin(80.0 * kPi / 180.0);
  for (const auto& [projection, share] :
       {std::pair{"projection=hemispherical", 1.0}, std::pair{"projection=voxel_slices", 1.0},
        std::pair{"projection=perspective", 4 * sin80 * std::atan(sin80) / kPi}}) {
    const image::Image image =
        test::renderOneFrame(scene, "hemispherical_gather", {projection, "tessellation=1"}, 32)
            .image;
    double sum = 0;
    for (float v : image.data()) sum += v;
    const double mean = sum / double(image.data().size());
    EXPECT_NEAR(mean, 0.75 + 0.125 * share, 0.01) << projection;
  }
}

// The slices hold what the paper sized: 6 faces × 64 slabs × 64² texels × 16 bytes = 25.2 MB.
TEST(HemisphericalGatherTechnique, VoxelSlicesTakeThePapersMemory) {
  const scene::Scene scene = scene::loadScene("cornell", {});
  const TechniqueRunResult r =
      test::renderOneFrame(scene, "hemispherical_gather", {"projection=voxel_slices"}, 16);
  bool found = false;
  for (const TechniqueStatistic& s : r.statistics)
    if (s.name == "voxel_slices_mb") {
      EXPECT_DOUBLE_EQ(s.value, 6.0 * 64 * 64 * 64 * 16 / 1e6);
      found = true;
    }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace gib::rt
