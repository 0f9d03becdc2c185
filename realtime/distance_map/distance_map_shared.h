// Distance maps (book §6.1, §7.3; realtime/distance_map/README.md), as C++ and GLSL both read
// them: the objects whose maps a cube-map array holds, the settings of the search along a ray,
// and the closed forms the search and the gather are built of (the linear search's ray
// parameter, the secant step of eq. 6.2 as the book's code has it, the solid angles of eqs. 7.6
// and 7.7), so that the tests evaluate the very functions the shaders run.
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

// Maps one array holds: one per specular object (book §6.3), or the one object a gather shades.
const int kMaxDistanceMapObjects = 8;
// The compute passes' work groups: 8 × 8 texels of one face.
const int kDistanceMapGroupSize = 8;
// The distance a texel that sees no surface stores (the sky, at infinity): every point of a ray
// is nearer, so a search through it undershoots and ends in the direction of the ray.
const float kDistanceMapNoSurface = 1.0e30f;

// search=: how a ray's hit is found in a map (§6.1).
const int kSearchEnvironment = 0;  // classic environment mapping: the map in the ray's direction
const int kSearchParallax = 1;     // eq. 6.1: the hit as if the surface were perpendicular
const int kSearchLinear = 2;       // §6.1.2: march, take the first overshooting point
const int kSearchSecant = 3;       // §6.1.3: march, then secant steps (eq. 6.2 corrected)
// fresnel=: eq. 1.6's approximation (the book's shaders) or the exact functions.
const int kFresnelSchlick = 0;
const int kFresnelExact = 1;

// An object with a map: layer 6·index + face of the array.
struct DistanceMapObject {
  vec4 reference_point;  // xyz: o, where the map was taken from; w unused
  ivec4 triangles;       // x: first triangle of the object in the scene's list, y: one past it
};

// The uniform block the composing pass and every pass that reads the maps share.
struct DistanceMapBlock {
  DistanceMapObject objects[kMaxDistanceMapObjects];
  ivec4 counts;  // x: objects, y: face resolution N of the maps
  ivec4 search;  // x: method (kSearch…), y: linear steps, z: secant steps, w: fresnel
};

// The ray parameter of the linear search's sample t ∈ [0, 1) (§6.1.2): the point of the ray
// x + R·d whose direction from o is that of s(1 − t) + e·t, s and e the ray's start and end
// projected onto the unit sphere; |x| is the ray origin's distance from o, R a unit vector.
GIB_SHARED_FUNCTION float linearSearchParameter(float origin_distance, float t) {
  return origin_distance * t / (1.0f - t);
}

// One secant step between an undershooting ray parameter d_l and an overshooting d_p, whose
// points l and p have |l|/|l′| and |p|/|p′| (the point's distance from o over the map's in its
// direction). Eq. 6.2 as the book prints it has |l′|/|l′| and |p′|/|p′|, which are 1; its code
// (and the derivation from l′ = l·|l′|/|l|) has these ratios.
GIB_SHARED_FUNCTION float secantParameter(float d_l, float d_p, float l_ratio, float p_ratio) {
  return d_l + (d_p - d_l) * (1.0f - l_ratio) / (p_ratio - l_ratio);
}

// Eq. 7.6: the solid angle of a small surface of area A at distance d whose normal makes angle θ
// with the direction to it, A·cos θ / d².
GIB_SHARED_FUNCTION float solidAngleDifferential(float area_cos, float distance) {
  return area_cos / (distance * distance);
}

// Eq. 7.7: the solid angle of a disc of area A (times cos θ when tilted) at distance d on its
// axis, 2π(1 − 1/√(1 + A/(d²π))). Finite as d → 0 (2π), where eq. 7.6 diverges.
GIB_SHARED_FUNCTION float solidAngleDisc(float area_cos, float distance) {
  const float kPiValue = 3.14159265358979f;
  return 2.0f * kPiValue * (1.0f - 1.0f / sqrt(1.0f + area_cos / (distance * distance * kPiValue)));
}

// §7.3: the solid angle ω* under which a texel's surface Δy, seen from o under ω′ at distance
// |o − y|, is seen from x at distance |x − y|, by the disc's formula and the assumption that the
// surface's normal makes the same angle with both directions: with c = 1 − ω′/2π (so that
// A·cos θ/π = |o − y|²(1/c² − 1)) and q = |o − y|²/|x − y|², ω* = 2π(1 − c/√(c²(1 − q) + q)).
// The book prints 2π − (2π − ω′)/√((2π − ω′)²(1 − q) + q), which mixes ω′ with c: it is ω′ at
// q = 1 but 2π − 1 rather than 0 as x moves away (q → 0). Its shader computes c (`dw`, with
// `1*1*1` for |L|³) and drops the 2π(1 − ·) of this line.
GIB_SHARED_FUNCTION float solidAngleFromShadedPoint(float omega_reference, float reference_distance,
                                                    float shaded_distance) {
  const float kTwoPi = 6.28318530717959f;
  float q = (reference_distance * reference_distance) / (shaded_distance * shaded_distance);
  float c = 1.0f - omega_reference / kTwoPi;
  return kTwoPi * (1.0f - c / sqrt(c * c * (1.0f - q) + q));
}

#ifdef __cplusplus
static_assert(sizeof(DistanceMapObject) == 32, "std140: two vec4s");
static_assert(sizeof(DistanceMapBlock) == 32 * kMaxDistanceMapObjects + 32, "std140");
}  // namespace gib::rt::gpu
#endif
