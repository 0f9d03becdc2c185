// The scene's triangles as the GPU ray casters of book Ch. 5 hold them: one list over every mesh,
// each triangle as the inverse of its vertex matrix (IVM, §5.1) relative to its own apex. The
// book makes every IVM relative to the world's origin, and warns that a plane through the origin
// has none; worse, a plane that passes near it has an ill-conditioned one, whose barycentric
// coordinates lose digits in proportion to D²/(s·h) (D: the triangle's distance from the origin,
// s: its size, h: its plane's distance from the origin). A tessellated sphere has tangent planes
// through every point outside it, so no one origin serves all triangles: on the Cornell box's
// spheres the world-origin IVM put hits 0.3 mm across an edge (Δt 0.014 mm, 500 of 6 300 stress
// rays). Each triangle's apex, a point one longest edge above its centroid along its normal, makes
// h = s and D ≈ s: the IVM is as well conditioned as the triangle, for 3 floats more per triangle
// (in the texels' spare w), and the test subtracts the apex from the ray's origin first.
// The kd-tree and the BVH order these triangles as their leaves want; the ray engine reads them
// in list order; every cast names a hit by its index in this list.
#pragma once

#include "realtime/ray_casting/ray_casting_shared.h"
#include "scene/scene.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace gib::rt {

struct IvmTriangle {
  // The vertices relative to IvmTriangleSet::origin (what the builders bound).
  glm::vec3 a{0.0f}, b{0.0f}, c{0.0f};
  // The point the IVM is relative to: the centroid raised by the longest edge along the normal.
  glm::vec3 apex{0.0f};
  // The rows of the IVM, [a − apex, b − apex, c − apex]⁻¹, inverted in double precision.
  glm::vec3 rows[3];
  std::uint32_t mesh = 0;      // index into Scene::meshes
  std::uint32_t triangle = 0;  // index into that mesh's triangles
};

struct IvmTriangleSet {
  // The world point the vertices, apexes and structures are relative to (the scene's coordinates
  // moved to a point away from the triangles' planes): a ray's origin is moved by −origin before
  // it is cast (ivmRayOrigin).
  glm::dvec3 origin{0.0};
  std::vector<IvmTriangle> triangles;
  // Bounds of the triangles, relative to origin.
  glm::vec3 bounds_min{0.0f}, bounds_max{0.0f};
  // The smallest distance from origin to a triangle's plane, over every triangle, in scene units:
  // what the choice of origin achieved (the IVM's conditioning depends on it).
  double min_plane_distance = 0.0;
  // Triangles left out because they have no area (no ray hits them: Embree skips them too).
  std::size_t degenerate = 0;
  // first_of_mesh[m] + t is mesh m's triangle t's index, or, where triangles were left out,
  // look it up through indexOf.
  std::vector<std::uint32_t> first_of_mesh;
  std::vector<std::uint32_t> index_of;  // per scene triangle (meshes in order), or kNoRayTriangle

  // The list index of mesh `mesh`'s triangle `triangle`, kNoRayTriangle when it was left out.
  std::uint32_t indexOf(std::uint32_t mesh, std::uint32_t triangle) const;
  std::size_t size() const { return triangles.size(); }
};

// Every triangle of the scene with positive area, in mesh order. Throws gib::InputError when the
// scene has none ("a scene with no triangles").
IvmTriangleSet buildIvmTriangles(const scene::Scene& scene);

// A world-space ray origin in the set's coordinates.
glm::vec3 ivmRayOrigin(const IvmTriangleSet& set, const glm::vec3& world_origin);

// The kRayTriangleTexels texels of each triangle, in the order `order` gives (indices into the
// set), then the slots' set indices, four to a texel (ray_casting_shared.h).
std::vector<glm::vec4> packRayTriangles(const IvmTriangleSet& set,
                                        std::span<const std::uint32_t> order);

// The §5.1 test of triangle `index` against a ray in the set's coordinates, updating `hit` when
// it is nearer than hit.t (and beyond t_min): the CPU twin of the shaders' test.
void intersectIvmTriangle(const IvmTriangleSet& set, std::uint32_t index, const glm::vec3& o,
                          const glm::vec3& d, float t_min, gpu::RayCastHit& hit);

// The closest hit over every triangle (the brute force of §5.1): what the structures' CPU
// traversals are tested against. Ray in the set's coordinates.
gpu::RayCastHit castBruteForce(const IvmTriangleSet& set, const glm::vec3& o, const glm::vec3& d,
                               float t_min, float t_max);

// A miss.
inline gpu::RayCastHit noRayHit() {
  return {gpu::kRayInfinity, gpu::kNoRayTriangle, 0.0f, 0.0f};
}

}  // namespace gib::rt
