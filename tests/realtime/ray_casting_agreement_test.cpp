// Every GPU ray-casting structure (book Ch. 5: the §5.1 loop, the ray engine with and without
// cones, the loose kd-tree, the BVH) against Embree on rays built to stress ties: through the
// midpoints of shared edges, through shared vertices, at triangle centres, and grazing the walls
// a hair above them, on the Cornell box with its spheres (a tessellated sphere: thousands of
// shared edges and vertices). The tie rule is hit_comparison.h's; under it, no ray may differ.
#include "realtime/ray_casting/hit_comparison.h"
#include "realtime/ray_casting/ray_cast_pass.h"
#include "realtime/ray_casting/ray_engine.h"
#include "realtime/ray_casting/ray_structures.h"
#include "reference/embree_scene.h"
#include "scene/builtin_scenes.h"
#include "support/gl_test_context.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <random>

namespace gib {
namespace {

class RayCastingAgreement : public test::GlTest {};

// Rays from seeded points inside the box towards every edge midpoint, vertex and centre of a
// sample of triangles, and rays skimming each wall 10⁻³ mm above it.
std::vector<scene::Ray> stressRays(const scene::Scene& scene) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> inside(60.0f, 490.0f);
  std::vector<scene::Ray> rays;
  auto aim = [&](const glm::vec3& target) {
    const glm::vec3 origin(inside(random), inside(random), inside(random));
    if (glm::length(target - origin) < 1.0f) return;
    rays.push_back(
        {origin, glm::normalize(target - origin), 0.0f, std::numeric_limits<float>::infinity()});
  };
  for (const scene::Mesh& mesh : scene.meshes) {
    // Every triangle of the walls, every 37th of a sphere: about 1 500 triangles.
    const std::size_t step = mesh.triangles.size() > 100 ? 37 : 1;
    for (std::size_t t = 0; t < mesh.triangles.size(); t += step) {
      const glm::uvec3 tri = mesh.triangles[t];
      const glm::vec3 a = mesh.positions[tri.x], b = mesh.positions[tri.y],
                      c = mesh.positions[tri.z];
      for (const glm::vec3& target :
           {a, b, c, 0.5f * (a + b), 0.5f * (b + c), 0.5f * (c + a), (a + b + c) / 3.0f})
        aim(target);
    }
  }
  // Grazing: along the floor (y = 0) and the back wall (z = 559.2), 10⁻³ mm off them.
  for (int i = 0; i < 64; ++i) {
    const float s = 10.0f + 8.0f * float(i);
    rays.push_back({glm::vec3(s, 1e-3f, 1.0f), glm::normalize(glm::vec3(0.01f, 0.0f, 1.0f)), 0.0f,
                    std::numeric_limits<float>::infinity()});
    rays.push_back({glm::vec3(1.0f, s, 559.2f - 1e-3f), glm::vec3(1.0f, 0.0f, 0.0f), 0.0f,
                    std::numeric_limits<float>::infinity()});
  }
  return rays;
}

TEST_F(RayCastingAgreement, EveryStructureHitsWhatEmbreeHitsOnRaysThatStressTies) {
  const scene::Scene scene = scene::loadScene("cornell", {"spheres=mirror_glass"});
  const rt::IvmTriangleSet set = rt::buildIvmTriangles(scene);
  const std::vector<scene::Ray> rays = stressRays(scene);
  ASSERT_GT(rays.size(), 5000u);
  const ref::EmbreeScene embree(scene);
  std::vector<scene::RayHit> reference(rays.size());
  embree.intersect(rays, reference, false);
  const std::vector<rt::CastRay> cast = rt::castRaysOf(set, rays);
  const double tie = rt::tieDistance(set);
  auto expectAgreement = [&](std::string_view name, const std::vector<rt::gpu::RayCastHit>& hits) {
    const rt::HitComparison c = rt::compareHits(scene, set, rays, reference, hits, tie);
    EXPECT_EQ(c.mismatches, 0u) << name << ": " << c.wrong_triangle << " wrong triangles, "
                                << c.missed << " missed, " << c.extra << " extra of " << c.rays;
    // The rays aim at vertices and edges: some must land on the tie rule, or it was not tested.
    EXPECT_GT(c.same_triangle, rays.size() / 2) << name;
  };
  for (const std::string& name : rt::gpuRayStructureNames()) {
    const std::unique_ptr<rt::GpuRayStructure> structure = rt::makeGpuRayStructure(name, set);
    rt::RayCastPass pass(*structure);
    pass.setRays(cast);
    pass.cast();
    expectAgreement(name, pass.hits());
  }
  for (bool cones : {false, true}) {
    rt::RayEngine engine(set, cones);
    engine.setRays(cast, 128);
    engine.cast();
    expectAgreement(engine.name(), engine.hits());
  }
}

}  // namespace
}  // namespace gib
