#include "realtime/ray_casting/hit_comparison.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gib::rt {

namespace {

struct WorldTriangle {
  glm::dvec3 a, b, c;
};

WorldTriangle worldTriangle(const scene::Scene& scene, std::uint32_t mesh, std::uint32_t triangle) {
  const scene::Mesh& m = scene.meshes[mesh];
  const glm::uvec3& t = m.triangles[triangle];
  return {glm::dvec3(m.positions[t.x]), glm::dvec3(m.positions[t.y]), glm::dvec3(m.positions[t.z])};
}

double segmentDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double s = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::length(p - (a + s * ab));
}

// The distance from a point on (or next to) a triangle's plane to its boundary.
double boundaryDistance(const WorldTriangle& t, const glm::dvec3& p) {
  return std::min(
      {segmentDistance(p, t.a, t.b), segmentDistance(p, t.b, t.c), segmentDistance(p, t.c, t.a)});
}

// The distance from a point to a triangle: to its plane where the point projects inside it, else
// to its nearest edge.
double triangleDistance(const WorldTriangle& t, const glm::dvec3& p) {
  const glm::dvec3 n = glm::normalize(glm::cross(t.b - t.a, t.c - t.a));
  const glm::dvec3 projected = p - glm::dot(p - t.a, n) * n;
  auto side = [&](const glm::dvec3& u, const glm::dvec3& v) {
    return glm::dot(glm::cross(v - u, projected - u), n) >= 0.0;
  };
  if (side(t.a, t.b) && side(t.b, t.c) && side(t.c, t.a)) return std::abs(glm::dot(p - t.a, n));
  return boundaryDistance(t, p);
}

// Barycentric coordinates (of b and c) of p projected on the triangle's plane.
glm::dvec2 barycentric(const WorldTriangle& t, const glm::dvec3& p) {
  const glm::dvec3 e1 = t.b - t.a, e2 = t.c - t.a, w = p - t.a;
  const double d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
  const double w1 = glm::dot(w, e1), w2 = glm::dot(w, e2);
  const double det = d11 * d22 - d12 * d12;
  return {(d22 * w1 - d12 * w2) / det, (d11 * w2 - d12 * w1) / det};
}

glm::dvec3 pointOn(const scene::Ray& ray, double t) {
  return glm::dvec3(ray.origin) + t * glm::dvec3(ray.direction);
}

}  // namespace

double tieDistance(const IvmTriangleSet& set) {
  return kTieFraction * double(glm::length(set.bounds_max - set.bounds_min));
}

HitComparison compareHits(const scene::Scene& scene, const IvmTriangleSet& set,
                          std::span<const scene::Ray> rays,
                          std::span<const scene::RayHit> reference,
                          std::span<const gpu::RayCastHit> cast, double tie_distance) {
  if (reference.size() != rays.size() || cast.size() != rays.size())
    throw std::logic_error("compareHits: one hit per ray on both sides");
  HitComparison c;
  c.rays = rays.size();
  c.tie_distance = tie_distance;
  double sum_dt = 0.0, sum_b = 0.0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const scene::RayHit& e = reference[i];
    const gpu::RayCastHit& g = cast[i];
    const bool e_hit = e.valid();
    const bool g_hit = g.triangle != gpu::kNoRayTriangle;
    if (e_hit) ++c.reference_hits;
    if (!e_hit && !g_hit) continue;
    if (e_hit && g_hit) {
      const IvmTriangle& gt = set.triangles.at(g.triangle);
      if (gt.mesh == e.mesh && gt.triangle == e.triangle) {
        const double dt = std::abs(double(g.t) - double(e.t));
        const glm::dvec2 exact =
            barycentric(worldTriangle(scene, e.mesh, e.triangle), pointOn(rays[i], e.t));
        const double db = std::max(std::abs(g.u - exact.x), std::abs(g.v - exact.y));
        ++c.same_triangle;
        sum_dt += dt;
        sum_b += db;
        c.max_abs_dt = std::max(c.max_abs_dt, dt);
        c.max_barycentric_error = std::max(c.max_barycentric_error, db);
        continue;
      }
      const WorldTriangle g_triangle = worldTriangle(scene, gt.mesh, gt.triangle);
      const WorldTriangle e_triangle = worldTriangle(scene, e.mesh, e.triangle);
      const glm::dvec3 g_point = pointOn(rays[i], g.t), e_point = pointOn(rays[i], e.t);
      if (triangleDistance(e_triangle, g_point) <= tie_distance ||
          triangleDistance(g_triangle, e_point) <= tie_distance) {
        ++c.ties;  // the same surface: a shared edge or vertex, coplanar, or grazed
      } else if (boundaryDistance(g.t < e.t ? g_triangle : e_triangle,
                                  g.t < e.t ? g_point : e_point) <= tie_distance) {
        ++c.ties;  // the nearer hit grazes its triangle's edge: the other side passed by it
      } else {
        ++c.wrong_triangle;
      }
      continue;
    }
    // One side hit, the other missed: a tie where the hit grazes its triangle's boundary.
    const WorldTriangle hit_triangle = e_hit
                                           ? worldTriangle(scene, e.mesh, e.triangle)
                                           : worldTriangle(scene, set.triangles.at(g.triangle).mesh,
                                                           set.triangles.at(g.triangle).triangle);
    const double t = e_hit ? double(e.t) : double(g.t);
    if (boundaryDistance(hit_triangle, pointOn(rays[i], t)) <= tie_distance)
      ++c.ties;
    else if (e_hit)
      ++c.missed;
    else
      ++c.extra;
  }
  c.mismatches = c.wrong_triangle + c.missed + c.extra;
  if (c.same_triangle > 0) {
    c.mean_abs_dt = sum_dt / double(c.same_triangle);
    c.mean_barycentric_error = sum_b / double(c.same_triangle);
  }
  return c;
}

}  // namespace gib::rt
