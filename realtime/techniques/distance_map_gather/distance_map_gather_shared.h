// `distance_map_gather` (book §7.3, §4.2.2) as C++ and GLSL both read it: its texture units, the
// choices of its parameters, and the closed forms of the gather (a low-resolution texel's
// direction on the cube of edge 2, its solid angle seen from the reference point o and from the
// shaded point x, the glossy lobe's cut-off) and of the irradiance map (a cube texel's exact
// solid angle), so that the tests evaluate the very functions the shaders run.
#pragma once
#include "realtime/distance_map/distance_map_shared.h"
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace gib::rt::gpu {
using glm::atan;
using glm::length;
using glm::max;
using glm::pow;
using glm::sqrt;
#endif

// The downsampled maps (M² texels per face, or the irradiance map's 16² source), sampled nearest
// at texel centres.
const int kLowResMapUnit = kTechniqueFirstUnit + 0;
// mode=irradiance_map: cube 0 the diffuse irradiance map, cube 1 the glossy map (§4.2.2).
const int kIrradianceMapUnit = kTechniqueFirstUnit + 1;

// mode=
const int kGatherFromDistanceMap = 0;
const int kGatherFromIrradianceMap = 1;
// solid_angle=: eq. 7.7 (a disc) or eq. 7.6 (a small planar polygon: A cos θ / d²).
const int kSolidAngleDisc = 0;
const int kSolidAnglePolygon = 1;

// The irradiance map: 16² texels per face, convolved from the map averaged to 16² per face (a
// texel of 5.6° at most, against a cosine lobe or a shininess-5 lobe tens of degrees wide).
const int kIrradianceMapSize = 16;
const int kIrradianceSourceSize = 16;
const int kIrradianceGroupSize = 8;

// A downsampled texel whose mean distance exceeds this sees the sky (kDistanceMapNoSurface) in
// some of its texels: a light at infinity, seen from x in the same direction and solid angle.
const float kGatherSkyDistance = 1.0e20f;

// visibility=true: a shadow ray leaves the shaded point this fraction of the scene's diagonal off
// its surface along the normal, and stops this fraction of its length short of the texel's mean
// point: that point averages the distances of the texel's surfaces and lies in front of or behind
// them (inside the emitting cube of the tests, a stop 2% short still met the texel's own wall, 10%
// short did not), so an occluder counts when it is nearer than three quarters of the way.
const float kGatherRayOffsetFraction = 1.0e-4f;
const float kGatherRayShortfall = 0.25f;

// glossy_peak_only: a texel is gathered when the Phong lobe cosⁿα in its direction is at least
// this fraction of the lobe's peak (n = 5: α ≤ 50.9°).
const float kGlossyPeakFraction = 0.1f;

// The centre of texel (i, j) of face `face` (OpenGL's order +x −x +y −y +z −z, j the row in
// memory) of an M × M face on the cube of edge 2 round o: the book's L, not normalised (one of
// its coordinates is ±1). OpenGL's table of face axes (spec §8.13), as sh::cubeTexelDirection.
GIB_SHARED_FUNCTION vec3 cubeTexelVector(int face, int i, int j, int size) {
  float s = 2.0f * (float(i) + 0.5f) / float(size) - 1.0f;
  float t = 2.0f * (float(j) + 0.5f) / float(size) - 1.0f;
  if (face == 0) return vec3(1.0f, -t, -s);
  if (face == 1) return vec3(-1.0f, -t, s);
  if (face == 2) return vec3(s, 1.0f, t);
  if (face == 3) return vec3(s, -1.0f, -t);
  if (face == 4) return vec3(s, -t, 1.0f);
  return vec3(-s, -t, -1.0f);
}

// ω′ of a texel of an M × M face seen from o, its centre at L (|L| ≥ 1): the texel's area is
// (2/M)² (the book prints 2/M), its distance |L| and cos θ = 1/|L|, so A·cos θ/d² = 4/(M²|L|³);
// eq. 7.7 (kSolidAngleDisc) or eq. 7.6 (kSolidAnglePolygon).
GIB_SHARED_FUNCTION float texelSolidAngle(float texel_distance, int size, int method) {
  float area = 4.0f / float(size * size);
  float area_cos = area / texel_distance;
  if (method == kSolidAnglePolygon) return solidAngleDifferential(area_cos, texel_distance);
  return solidAngleDisc(area_cos, texel_distance);
}

// ω* of that texel's surface seen from x: eq. 7.7's relation (solidAngleFromShadedPoint), or
// eq. 7.6 carried from o to x, A cos θ/|x − y|² = ω′·|o − y|²/|x − y|² (the same angle between the
// surface's normal and both directions, as the book assumes).
GIB_SHARED_FUNCTION float shadedSolidAngle(float omega_reference, float reference_distance,
                                           float shaded_distance, int method) {
  if (method == kSolidAnglePolygon)
    return omega_reference * (reference_distance * reference_distance) /
           (shaded_distance * shaded_distance);
  return solidAngleFromShadedPoint(omega_reference, reference_distance, shaded_distance);
}

// The smallest cos α between the lobe's peak and a direction gathered with glossy_peak_only:
// cosⁿα = kGlossyPeakFraction.
GIB_SHARED_FUNCTION float glossyPeakCosine(float exponent) {
  return pow(kGlossyPeakFraction, 1.0f / max(exponent, 1.0e-3f));
}

// The exact solid angle of the part of the face z = 1 over [0, x] × [0, y], signed.
GIB_SHARED_FUNCTION float cubeCornerSolidAngle(float x, float y) {
  return atan(x * y, sqrt(x * x + y * y + 1.0f));
}

// The exact solid angle of texel (i, j) of an M × M face (the same on every face); the texels of
// a cube sum to 4π.
GIB_SHARED_FUNCTION float cubeTexelExactSolidAngle(int i, int j, int size) {
  float x0 = 2.0f * float(i) / float(size) - 1.0f, x1 = 2.0f * float(i + 1) / float(size) - 1.0f;
  float y0 = 2.0f * float(j) / float(size) - 1.0f, y1 = 2.0f * float(j + 1) / float(size) - 1.0f;
  return cubeCornerSolidAngle(x1, y1) - cubeCornerSolidAngle(x0, y1) -
         cubeCornerSolidAngle(x1, y0) + cubeCornerSolidAngle(x0, y0);
}

#ifdef __cplusplus
static_assert(kIrradianceMapUnit < kTechniqueFirstUnit + kTechniqueUnitCount,
              "a technique has four texture units");
static_assert(kIrradianceMapSize % kIrradianceGroupSize == 0, "whole work groups");
}  // namespace gib::rt::gpu
#endif
