#include "realtime/ray_casting/ivm_triangles.h"

#include "common/input_error.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace gib::rt {

namespace {

// A triangle whose doubled area is below this fraction of its squared longest edge is a sliver
// with no area: left out, as Embree's intersector never reports a hit on it either.
constexpr double kDegenerateFraction = 1e-12;

// Candidates for the origin: a kOriginGrid³ lattice over the scene's bounds, cell centres (so
// none lies on the walls of a box-shaped scene). 7³ = 343 candidates against every triangle's
// plane is a few tens of milliseconds on the chamber at detail 5.
constexpr int kOriginGrid = 7;

struct PlaneOf {
  glm::dvec3 normal;  // unit
  double offset;      // normal·x = offset on the plane
};

}  // namespace

std::uint32_t IvmTriangleSet::indexOf(std::uint32_t mesh, std::uint32_t triangle) const {
  if (mesh >= first_of_mesh.size()) return gpu::kNoRayTriangle;
  const std::size_t i = first_of_mesh[mesh] + std::size_t{triangle};
  return i < index_of.size() ? index_of[i] : gpu::kNoRayTriangle;
}

IvmTriangleSet buildIvmTriangles(const scene::Scene& scene) {
  IvmTriangleSet set;
  // World-space triangles with area, and their planes.
  struct WorldTriangle {
    glm::dvec3 a, b, c;
    std::uint32_t mesh, triangle;
  };
  std::vector<WorldTriangle> world;
  std::vector<PlaneOf> planes;
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  std::uint32_t scene_triangles = 0;
  for (std::uint32_t m = 0; m < scene.meshes.size(); ++m) {
    const scene::Mesh& mesh = scene.meshes[m];
    set.first_of_mesh.push_back(scene_triangles);
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t, ++scene_triangles) {
      const glm::uvec3& tri = mesh.triangles[t];
      const glm::dvec3 a(mesh.positions[tri.x]), b(mesh.positions[tri.y]), c(mesh.positions[tri.z]);
      const glm::dvec3 n = glm::cross(b - a, c - a);
      const double longest =
          std::max({glm::dot(b - a, b - a), glm::dot(c - b, c - b), glm::dot(a - c, a - c)});
      if (!(glm::length(n) > kDegenerateFraction * longest)) {
        set.index_of.push_back(gpu::kNoRayTriangle);
        ++set.degenerate;
        continue;
      }
      set.index_of.push_back(static_cast<std::uint32_t>(world.size()));
      world.push_back({a, b, c, m, t});
      const glm::dvec3 unit = glm::normalize(n);
      planes.push_back({unit, glm::dot(unit, a)});
      lo = glm::min(lo, glm::min(a, glm::min(b, c)));
      hi = glm::max(hi, glm::max(a, glm::max(b, c)));
    }
  }
  if (world.empty())
    throw InputError(
        "the scene has no triangles with area to cast rays against; give a scene with surfaces");

  // The origin: the lattice point farthest from every triangle's plane (ties: the first in
  // lattice order, so the choice is deterministic).
  double best = -1.0;
  glm::dvec3 origin = 0.5 * (lo + hi);
  for (int k = 0; k < kOriginGrid; ++k)
    for (int j = 0; j < kOriginGrid; ++j)
      for (int i = 0; i < kOriginGrid; ++i) {
        const glm::dvec3 f((i + 0.5) / kOriginGrid, (j + 0.5) / kOriginGrid,
                           (k + 0.5) / kOriginGrid);
        const glm::dvec3 p = lo + f * (hi - lo);
        double nearest = std::numeric_limits<double>::max();
        for (const PlaneOf& plane : planes) {
          nearest = std::min(nearest, std::abs(glm::dot(plane.normal, p) - plane.offset));
          if (nearest <= best) break;  // cannot beat the best any more
        }
        if (nearest > best) {
          best = nearest;
          origin = p;
        }
      }
  set.origin = origin;
  set.min_plane_distance = best;

  set.triangles.reserve(world.size());
  glm::vec3 bmin(std::numeric_limits<float>::max()), bmax(-std::numeric_limits<float>::max());
  for (const WorldTriangle& w : world) {
    IvmTriangle t;
    const glm::dvec3 a = w.a - origin, b = w.b - origin, c = w.c - origin;
    t.a = glm::vec3(a);
    t.b = glm::vec3(b);
    t.c = glm::vec3(c);
    // The apex, rounded to float first so that the stored apex and rows agree.
    const glm::dvec3 normal = glm::normalize(glm::cross(b - a, c - a));
    const double longest = std::sqrt(
        std::max({glm::dot(b - a, b - a), glm::dot(c - b, c - b), glm::dot(a - c, a - c)}));
    t.apex = glm::vec3((a + b + c) / 3.0 + longest * normal);
    const glm::dvec3 apex(t.apex);
    // [a b c] − apex has the vertices as columns; its inverse's rows are what b = IVM·p dots with.
    const glm::dmat3 inverse = glm::inverse(glm::dmat3(a - apex, b - apex, c - apex));
    for (int r = 0; r < 3; ++r) t.rows[r] = glm::vec3(inverse[0][r], inverse[1][r], inverse[2][r]);
    t.mesh = w.mesh;
    t.triangle = w.triangle;
    bmin = glm::min(bmin, glm::min(t.a, glm::min(t.b, t.c)));
    bmax = glm::max(bmax, glm::max(t.a, glm::max(t.b, t.c)));
    set.triangles.push_back(t);
  }
  set.bounds_min = bmin;
  set.bounds_max = bmax;
  return set;
}

glm::vec3 ivmRayOrigin(const IvmTriangleSet& set, const glm::vec3& world_origin) {
  return glm::vec3(glm::dvec3(world_origin) - set.origin);
}

std::vector<glm::vec4> packRayTriangles(const IvmTriangleSet& set,
                                        std::span<const std::uint32_t> order) {
  std::vector<glm::vec4> texels;
  texels.reserve(order.size() * gpu::kRayTriangleTexels + (order.size() + 3) / 4);
  for (std::uint32_t index : order) {
    const IvmTriangle& t = set.triangles.at(index);
    for (int r = 0; r < 3; ++r) texels.emplace_back(t.rows[r], t.apex[r]);
  }
  for (std::size_t slot = 0; slot < order.size(); slot += 4) {
    glm::vec4 indices(std::bit_cast<float>(gpu::kNoRayTriangle));
    for (std::size_t k = 0; k < 4 && slot + k < order.size(); ++k)
      indices[int(k)] = std::bit_cast<float>(order[slot + k]);
    texels.push_back(indices);
  }
  return texels;
}

void intersectIvmTriangle(const IvmTriangleSet& set, std::uint32_t index, const glm::vec3& o,
                          const glm::vec3& d, float t_min, gpu::RayCastHit& hit) {
  const IvmTriangle& t = set.triangles[index];
  const glm::vec4 r =
      gpu::intersectIvm(o - t.apex, d, t.rows[0], t.rows[1], t.rows[2], t_min, hit.t);
  if (r.x < hit.t) hit = {r.x, index, r.z, r.w};
}

gpu::RayCastHit castBruteForce(const IvmTriangleSet& set, const glm::vec3& o, const glm::vec3& d,
                               float t_min, float t_max) {
  gpu::RayCastHit hit = noRayHit();
  hit.t = t_max;
  for (std::uint32_t i = 0; i < set.triangles.size(); ++i)
    intersectIvmTriangle(set, i, o, d, t_min, hit);
  if (hit.triangle == gpu::kNoRayTriangle) hit.t = gpu::kRayInfinity;
  return hit;
}

}  // namespace gib::rt
