// Depth peeling (realtime/depth_peeling/depth_peeler.h): every surface a bundle's ray crosses is
// found, in order, as Embree finds them along the same ray; the epsilon merges surfaces closer
// than it and keeps farther ones apart; records carry the patch, the facing and the depth.
#include "realtime/depth_peeling/depth_peeler.h"

#include "common/input_error.h"
#include "realtime/atlas/atlas_layout.h"
#include "realtime/atlas/atlas_mesh.h"
#include "realtime/depth_peeling/depth_peeling_shared.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "reference/embree_scene.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"
#include "support/gl_test_context.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <cmath>

namespace gib::rt {
namespace {

class DepthPeelingTest : public test::GlTest {};

struct PeeledScene {
  explicit PeeledScene(const scene::Scene& s, int resolution, int max_layers)
      : scene(s),
        gpu(scene, 16, 16),
        triangles(atlas::atlasTriangles(scene)),
        layout(atlas::layoutAtlas(triangles, 64)),
        mesh(triangles, layout, 0),
        peeler(resolution, max_layers, 0.5f * (gpu.boundsMin() + gpu.boundsMax()),
               0.5f * glm::length(gpu.boundsMax() - gpu.boundsMin()) * 1.01f) {}
  scene::Scene scene;
  GpuScene gpu;
  std::vector<atlas::AtlasTriangle> triangles;
  atlas::AtlasLayout layout;
  atlas::AtlasMesh mesh;
  DepthPeeler peeler;
};

// The world point where pixel (x, y)'s ray leaves the projection plane.
glm::vec3 rayOrigin(const PeelProjection& p, int resolution, int x, int y) {
  const glm::vec4 clip(2.0f * (float(x) + 0.5f) / float(resolution) - 1.0f,
                       2.0f * (float(y) + 0.5f) / float(resolution) - 1.0f, -1.0f, 1.0f);
  const glm::vec4 world = glm::inverse(p.clip_from_world) * clip;
  return glm::vec3(world) / world.w;
}

// Surfaces Embree finds along the ray, counting two closer than `epsilon` as one (the peeler's
// rule).
int embreeSurfaces(const scene::RayCaster& caster, glm::vec3 origin, glm::vec3 direction,
                   float epsilon) {
  int count = 0;
  float t_near = 0.0f;
  for (;;) {
    const scene::RayHit hit = caster.intersect(origin, direction, t_near);
    if (!hit.valid()) return count;
    ++count;
    t_near = hit.t + epsilon;
  }
}

TEST_F(DepthPeelingTest, FindsEverySurfaceEmbreeFindsAlongEachRay) {
  PeeledScene s(scene::loadScene("cornell", {}), 96, 16);
  const std::unique_ptr<scene::RayCaster> caster = ref::embreeRayCasterFactory()(s.scene);
  for (const glm::vec3 direction :
       {glm::vec3(0.3f, -0.8f, 0.52f), glm::vec3(-0.61f, 0.2f, -0.77f), glm::vec3(0, 0, 1)}) {
    const PeelBundle bundle{glm::normalize(direction), {0.37f, 0.71f}};
    const int layers = s.peeler.peel(s.mesh, bundle);
    ASSERT_LT(layers, 16) << "a ray crossed more surfaces than the test's max_layers";
    const std::vector<int> peeled = s.peeler.surfacesPerPixel();
    const PeelProjection p = s.peeler.projection(bundle);
    const int n = s.peeler.resolution();
    int differing = 0, most = 0, max_difference = 0;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const int expected =
            embreeSurfaces(*caster, rayOrigin(p, n, x, y), p.direction, s.peeler.epsilon());
        const int got = peeled[std::size_t(y * n + x)];
        most = std::max(most, expected);
        if (got != expected) ++differing;
        max_difference = std::max(max_difference, std::abs(got - expected));
      }
    EXPECT_EQ(layers, most);
    // The rasteriser snaps vertices to its sub-pixel grid and Embree does not: a ray through a
    // pixel centre within a sub-pixel of a triangle's edge may be counted on one side by one and
    // on the other by the other (the stated resolution); at an edge of a closed object (a box's
    // silhouette) that is both its faces, 2 surfaces. Nowhere else may they differ.
    EXPECT_LE(differing, n * n / 200) << differing << " of " << n * n << " pixels differ";
    EXPECT_LE(max_difference, 2);
  }
}

// Two parallel squares facing the bundle, `gap` apart along it.
scene::Scene twoSquares(float gap) {
  scene::Scene scene = scene::loadScene("cornell", {});
  scene.meshes.clear();
  scene.spot_lights.clear();
  scene.directional_lights.clear();
  scene::Mesh a, b;
  scene::appendQuad(a, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0});
  scene::appendQuad(b, {-1, -1, -gap}, {1, -1, -gap}, {1, 1, -gap}, {-1, 1, -gap});
  scene.meshes = {a, b};
  return scene;
}

TEST_F(DepthPeelingTest, EpsilonMergesSurfacesCloserThanItAndSeparatesFartherOnes) {
  for (const float factor : {0.5f, 4.0f}) {
    // The bounding sphere, hence ε, hardly depends on the gap: find ε first, then place the gap.
    const float epsilon = PeeledScene(twoSquares(0.0f), 16, 4).peeler.epsilon();
    PeeledScene s(twoSquares(factor * epsilon), 16, 4);
    ASSERT_NEAR(s.peeler.epsilon(), epsilon, 1e-3f * epsilon);
    const int layers = s.peeler.peel(s.mesh, {glm::vec3(0, 0, -1), {0.5f, 0.5f}});
    EXPECT_EQ(layers, factor < 1 ? 1 : 2) << "gap " << factor << " ε";
  }
}

TEST_F(DepthPeelingTest, RecordsCarryThePatchFacingAndDepth) {
  PeeledScene s(twoSquares(0.5f), 32, 4);
  // Along −z the square at z = 0 comes first and faces the bundle's origin (its normal is +z).
  const PeelBundle bundle{glm::vec3(0, 0, -1), {0.0f, 0.0f}};
  ASSERT_EQ(s.peeler.peel(s.mesh, bundle), 2);
  const PeelProjection p = s.peeler.projection(bundle);
  const int n = s.peeler.resolution();
  const std::vector<glm::vec4> first = s.peeler.layerTexels(0), second = s.peeler.layerTexels(1);
  const int centre = (n / 2) * n + n / 2;
  const glm::vec3 origin = rayOrigin(p, n, n / 2, n / 2);
  EXPECT_EQ(first[std::size_t(centre)].z, gpu::kPeelFrontFacing);
  EXPECT_EQ(second[std::size_t(centre)].z, gpu::kPeelFrontFacing);
  EXPECT_NEAR(first[std::size_t(centre)].w, origin.z - 0.0f, 1e-4f);
  EXPECT_NEAR(second[std::size_t(centre)].w - first[std::size_t(centre)].w, 0.5f, 1e-4f);
  // The patch address lies inside the atlas rectangle of the square it names.
  const auto insideChart = [&](glm::vec2 uv, int mesh) {
    const atlas::ChartRect& r =
        s.layout.charts[std::size_t(s.layout.chart_of_triangle[std::size_t(2 * mesh)])];
    const glm::vec2 texel = uv * float(s.layout.resolution);
    return texel.x >= float(r.x) && texel.x <= float(r.x + r.width) && texel.y >= float(r.y) &&
           texel.y <= float(r.y + r.height);
  };
  EXPECT_TRUE(insideChart(glm::vec2(first[std::size_t(centre)]), 0));
  EXPECT_TRUE(insideChart(glm::vec2(second[std::size_t(centre)]), 1));
  // Seen from the other side, both face away.
  ASSERT_EQ(s.peeler.peel(s.mesh, {glm::vec3(0, 0, 1), {0.0f, 0.0f}}), 2);
  EXPECT_EQ(s.peeler.layerTexels(0)[std::size_t(centre)].z, gpu::kPeelBackFacing);
}

TEST_F(DepthPeelingTest, RefusesImpossibleSizes) {
  EXPECT_THROW(DepthPeeler(1, 4, glm::vec3(0.0f), 1.0f), InputError);
  EXPECT_THROW(DepthPeeler(16, 0, glm::vec3(0.0f), 1.0f), InputError);
}

}  // namespace
}  // namespace gib::rt
