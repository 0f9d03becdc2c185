// Whether a GPU structure found the hits Embree finds, ray by ray, with the tie rule that makes
// "the same hit" well defined where two answers are equally right (realtime/ray_casting/README.md,
// "The tie rule"):
//   - both miss, or both hit the same triangle: agree;
//   - both hit, different triangles: a tie when either hit point lies within δ of the other's
//     triangle (a ray through an edge or a vertex two triangles share, coplanar triangles, or a
//     ray grazing a surface, where the two points may be far apart along the ray yet on the same
//     surface), or when the nearer of the two hits lies within δ of its triangle's boundary (a
//     ray through a silhouette edge, which one side took and the other passed by), else a
//     mismatch (wrong triangle);
//   - one hits, the other misses: a tie when the hit point lies within δ of its triangle's
//     boundary (a ray grazing an edge or a silhouette: a miss is a hit at infinity, so this is
//     the rule above), else a mismatch (missed or extra hit);
// δ = kTieFraction × the scene's bounding-box diagonal. |Δt| and the barycentric error are
// measured over the rays where both hit the same triangle, against Embree's t and the exact
// (double-precision) barycentric coordinates of Embree's hit point.
#pragma once

#include "realtime/ray_casting/ivm_triangles.h"
#include "scene/ray_caster.h"
#include "scene/scene.h"

#include <cstddef>
#include <span>

namespace gib::rt {

// 10⁻⁵ of the diagonal: above float's rounding of a hit point's coordinates (2⁻²⁴ relative,
// times the few operations of a test) and of the IVM's edge tolerance (kIvmEdgeTolerance of a
// triangle's size), far below any gap between surfaces a scene models (the chamber's thinnest
// is 10⁻³ of its diagonal).
inline constexpr double kTieFraction = 1e-5;

struct HitComparison {
  std::size_t rays = 0;
  std::size_t reference_hits = 0;  // rays Embree finds a hit for
  std::size_t mismatches = 0;      // wrong_triangle + missed + extra
  std::size_t wrong_triangle = 0;  // both hit, different triangles farther apart than δ
  std::size_t missed = 0;          // Embree hits, the GPU misses, away from an edge
  std::size_t extra = 0;           // the GPU hits, Embree misses, away from an edge
  std::size_t ties = 0;            // differences the tie rule accepts
  std::size_t same_triangle = 0;   // rays |Δt| and the barycentric error are taken over
  double max_abs_dt = 0.0, mean_abs_dt = 0.0;
  double max_barycentric_error = 0.0, mean_barycentric_error = 0.0;
  double tie_distance = 0.0;  // δ, scene units
};

// δ for a scene: kTieFraction × the diagonal of the set's bounds.
double tieDistance(const IvmTriangleSet& set);

// Compares `cast` (a structure's hits, IvmTriangleSet indices) with `reference` (Embree's) for
// the world-space `rays` both were given; all three spans have one entry per ray.
HitComparison compareHits(const scene::Scene& scene, const IvmTriangleSet& set,
                          std::span<const scene::Ray> rays,
                          std::span<const scene::RayHit> reference,
                          std::span<const gpu::RayCastHit> cast, double tie_distance);

}  // namespace gib::rt
