// The ray engine (book §5.2–5.3): the depth test keeps the nearest hit (every ray equals the §5.1
// brute force on the CPU), and the cones of §5.3 enclose their tile's rays (every origin inside,
// every direction within the half angle), so culling by them cannot lose a hit, while they keep
// few (tile, triangle) pairs for coherent rays.
#include "realtime/ray_casting/ray_engine.h"
#include "realtime/ray_casting/ray_engine_shared.h"
#include "realtime/ray_casting/ray_sets.h"
#include "reference/embree_scene.h"
#include "scene/builtin_scenes.h"
#include "support/gl_test_context.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

namespace gib {
namespace {

class RayEngine : public test::GlTest {};

TEST_F(RayEngine, KeepsTheNearestHitOfEveryRayWithAndWithoutCones) {
  const scene::Scene scene = scene::loadScene("chamber", {"detail=1"});
  const rt::IvmTriangleSet set = rt::buildIvmTriangles(scene);
  const std::unique_ptr<scene::RayCaster> caster = ref::embreeRayCasterFactory()(scene);
  for (rt::RayKind kind : {rt::RayKind::kPrimary, rt::RayKind::kReflection}) {
    const std::vector<rt::CastRay> rays =
        rt::castRaysOf(set, rt::makeRaySet(scene, kind, 40, 30, 1, *caster));
    for (bool cones : {false, true}) {
      rt::RayEngine engine(set, cones, 8);
      engine.setRays(rays, 40);
      engine.cast();
      const std::vector<rt::gpu::RayCastHit> hits = engine.hits();
      std::size_t differ = 0;
      for (std::size_t i = 0; i < rays.size(); ++i) {
        const rt::gpu::RayCastHit cpu = rt::castBruteForce(set, rays[i].origin, rays[i].direction,
                                                           rays[i].t_min, rays[i].t_max);
        // The same triangle, or one at the same distance (a shared edge: the depth test and the
        // CPU loop may break the tie differently).
        if (cpu.triangle != hits[i].triangle && std::abs(cpu.t - hits[i].t) > 1e-3f) ++differ;
      }
      EXPECT_EQ(differ, 0u) << engine.name() << " " << rt::rayKindName(kind);
    }
  }
}

TEST_F(RayEngine, ConesEncloseTheirTilesRaysAndCullCoherentOnes) {
  const scene::Scene scene = scene::loadScene("chamber", {"detail=1"});
  const rt::IvmTriangleSet set = rt::buildIvmTriangles(scene);
  const std::unique_ptr<scene::RayCaster> caster = ref::embreeRayCasterFactory()(scene);
  const int width = 64, tile = 16;
  for (rt::RayKind kind :
       {rt::RayKind::kPrimary, rt::RayKind::kReflection, rt::RayKind::kDiffuse}) {
    const std::vector<rt::CastRay> rays =
        rt::castRaysOf(set, rt::makeRaySet(scene, kind, width, 48, 3, *caster));
    rt::RayEngine engine(set, true, tile);
    engine.setRays(rays, width);
    engine.cast();
    // The cones as the vertex shader read them: every ray of a tile must lie in its cone.
    const double kept = engine.keptPairFraction();
    EXPECT_GT(kept, 0.0);
    EXPECT_LE(kept, 1.0);
    if (kind == rt::RayKind::kPrimary) {
      EXPECT_LT(kept, 0.2) << "primary rays share their apex";
    }
    // A sphere of radius 0 at a point along each ray, 1 to 10 units out, must meet its tile's
    // cone: the containment the culling relies on, checked through the same shared test.
    std::size_t outside = 0;
    const std::vector<glm::vec4> cones = engine.readCones();
    const int tiles_x = (width + tile - 1) / tile;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const int x = int(i % width), y = int(i / width);
      const std::size_t t = std::size_t((y / tile) * tiles_x + x / tile);
      for (float s : {1.0f, 10.0f}) {
        const glm::vec4 point(rays[i].origin + s * glm::normalize(rays[i].direction), 0.0f);
        if (!rt::gpu::sphereMeetsCone(point, cones[2 * t], cones[2 * t + 1])) ++outside;
      }
    }
    EXPECT_EQ(outside, 0u) << rt::rayKindName(kind);
  }
}

}  // namespace
}  // namespace gib
