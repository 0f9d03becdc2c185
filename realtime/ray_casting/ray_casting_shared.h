// GPU ray casting (book Ch. 5; realtime/ray_casting/README.md), written once for the CPU builders
// and their CPU traversals (which the tests hold the GPU to) and the shaders: the triangle record
// of §5.1 (the inverse of the vertex matrix, "IVM"), its intersection, the binding points every
// structure's traversal reads, and the hit a cast returns.
#pragma once
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

namespace gib::rt::gpu {
using glm::dot;
using glm::max;
using glm::min;
using glm::sqrt;
#endif

// A structure's data are buffer textures (llvmpipe gathers a texel fetch across a SIMD row;
// docs/architecture.md, "Declared GPU layouts") at kRayTrianglesUnit, kRayNodesUnit and
// kRayFlagsUnit (binding_plan_shared.h).

// A triangle is three RGBA32F texels: the rows of its IVM in xyz and, in their w, its apex: the
// point its IVM is relative to (IvmTriangle::apex). After every triangle's texels, the list index
// of the triangle in each slot (IvmTriangleSet order, as uint bits, four to a texel), so that a
// structure may order its triangles as its leaves want and still name them: a cast tracks the
// slot and looks the index up once, for the hit it returns.
const int kRayTriangleTexels = 3;

// The barycentric tolerance of the inside test: a point counts as inside when every barycentric
// coordinate is ≥ −(kIvmEdgeTolerance + kIvmRoundingTolerance·|o|·|q′|), o the ray's origin
// relative to the triangle's apex and 1/|q′| the apex's height above the plane (the triangle's
// longest edge, ivm_triangles.h). The book tests > 0, which lets a ray through an edge shared by
// two triangles miss both: each computes its coordinate a rounding error below zero, and that
// error grows with the ray's length over the triangle's size (the hit point o + t·d is a
// difference of two vectors |o| long), about 2⁻²⁴·|o|·|q′| times a few operations. The second
// term covers 64 such ulps; the first, 10⁻⁵ of the triangle, the error of the rows themselves. A
// hit accepted outside lies at most (10⁻⁵·s + 4·10⁻⁶·|o|) from the triangle: a tie for the
// comparison with Embree (hit_comparison.h).
const float kIvmEdgeTolerance = 1.0e-5f;
const float kIvmRoundingTolerance = 3.8e-6f;  // 2⁻¹⁸

// No triangle: the triangle field of a miss.
const uint kNoRayTriangle = 0xffffffffu;
// The t of a miss, and the far end of a ray that has none.
const float kRayInfinity = 3.0e38f;

// The closest hit of one ray: t along the ray (its direction as given, not necessarily unit), the
// triangle (IvmTriangleSet index, or kNoRayTriangle), and the barycentric weights of its second
// and third vertex (the first is 1 − u − v). std430: 16 bytes.
struct RayCastHit {
  float t;
  uint triangle;
  float u;
  float v;
};

// The book's §5.1 test for a ray o + t·d against the triangle whose IVM rows are r0, r1, r2, the
// ray's origin given relative to the triangle's apex (the point the IVM was made relative to):
// returns (t*, b) where the ray meets the triangle's plane at t* and b are the barycentric
// coordinates of that point, with t* = kRayInfinity when the ray meets the plane outside the
// triangle, outside (t_min, t_max), or not at all (parallel: the division gives ±∞ or NaN, which
// every comparison rejects).
// q′ = (1, 1, 1)·IVM is the plane's normal over its distance from the apex, so the plane is
// q′·x = 1 and t* = (1 − q′·o)/(q′·d): eq. 5.1–5.3's t* = (q·q − q·o)/(q·d) with q = q′/(q′·q′)
// substituted, which spares forming q and squaring it. (The book's listing declares q a float
// where it is a float3.)
GIB_SHARED_FUNCTION vec4 intersectIvm(vec3 o, vec3 d, vec3 r0, vec3 r1, vec3 r2, float t_min,
                                      float t_max) {
  vec3 q_prime = r0 + r1 + r2;
  float t = (1.0f - dot(q_prime, o)) / dot(q_prime, d);
  if (!(t > t_min && t < t_max)) return vec4(kRayInfinity, 0.0f, 0.0f, 0.0f);
  vec3 p = o + d * t;
  vec3 b = vec3(dot(r0, p), dot(r1, p), dot(r2, p));
  float tolerance =
      kIvmEdgeTolerance + kIvmRoundingTolerance * sqrt(dot(o, o) * dot(q_prime, q_prime));
  if (min(b.x, min(b.y, b.z)) < -tolerance) return vec4(kRayInfinity, 0.0f, 0.0f, 0.0f);
  return vec4(t, b.x, b.y, b.z);
}

#ifdef __cplusplus
}  // namespace gib::rt::gpu
#endif
