// The rays of the raycast bench (realtime/ray_casting/ray_sets.h): primary rays through every
// pixel centre, secondary rays from every primary hit, leaving the surface on the side the
// primary ray arrived from (mirror reflections exactly, diffuse ones within the hemisphere), and
// the same set on every call.
#include "realtime/ray_casting/ray_sets.h"
#include "common/input_error.h"
#include "reference/embree_scene.h"
#include "scene/builtin_scenes.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

namespace gib {
namespace {

TEST(RaySets, SecondaryRaysLeaveEveryPrimaryHitOnTheSideItArrivedFrom) {
  const scene::Scene scene = scene::loadScene("cornell", {});
  const std::unique_ptr<scene::RayCaster> caster = ref::embreeRayCasterFactory()(scene);
  const std::vector<scene::Ray> primary =
      rt::makeRaySet(scene, rt::RayKind::kPrimary, 24, 16, 1, *caster);
  ASSERT_EQ(primary.size(), 24u * 16u);
  std::vector<scene::RayHit> hits(primary.size());
  caster->intersect(primary, hits, true);
  std::size_t hit_count = 0;
  for (const scene::RayHit& h : hits) hit_count += h.valid() ? 1 : 0;
  for (rt::RayKind kind : {rt::RayKind::kReflection, rt::RayKind::kDiffuse}) {
    const std::vector<scene::Ray> rays = rt::makeRaySet(scene, kind, 24, 16, 1, *caster);
    EXPECT_EQ(rays.size(), hit_count);
    std::size_t j = 0;
    for (std::size_t i = 0; i < primary.size(); ++i) {
      if (!hits[i].valid()) continue;
      const scene::Mesh& mesh = scene.meshes[hits[i].mesh];
      const glm::uvec3 t = mesh.triangles[hits[i].triangle];
      glm::vec3 n = glm::normalize(glm::cross(mesh.positions[t.y] - mesh.positions[t.x],
                                              mesh.positions[t.z] - mesh.positions[t.x]));
      if (glm::dot(n, primary[i].direction) > 0) n = -n;
      const scene::Ray& r = rays[j++];
      EXPECT_NEAR(glm::length(r.direction), 1.0f, 1e-5f);
      EXPECT_GT(glm::dot(r.direction, n), 0.0f);
      if (kind == rt::RayKind::kReflection) {
        EXPECT_NEAR(glm::dot(r.direction, n), -glm::dot(primary[i].direction, n), 1e-5f);
      }
    }
  }
  // The diffuse set is a function of the seed alone.
  const auto a = rt::makeRaySet(scene, rt::RayKind::kDiffuse, 24, 16, 5, *caster);
  const auto b = rt::makeRaySet(scene, rt::RayKind::kDiffuse, 24, 16, 5, *caster);
  const auto c = rt::makeRaySet(scene, rt::RayKind::kDiffuse, 24, 16, 6, *caster);
  EXPECT_EQ(a[7].direction, b[7].direction);
  EXPECT_NE(a[7].direction, c[7].direction);
}

TEST(RaySets, NamesItsKindsAndRefusesOthers) {
  for (const std::string& name : rt::rayKindNames())
    EXPECT_EQ(rt::rayKindName(rt::parseRayKind(name)), name);
  EXPECT_THROW(rt::parseRayKind("shadow"), InputError);
}

}  // namespace
}  // namespace gib
