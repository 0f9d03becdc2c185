// What the coverage shaders and the weighting of jittered light sampling (Fournier & Péroche §4),
// on the GPU for the technique and on the CPU for the bench test, must agree on: where each
// sample of a pixel lies (the fragment shader tests the samples against the light's and the
// occluders' triangles; the weighting weighs each visible sample by the solid angle its stratum
// subtends at its own position, so both compute the same positions from the same hash), and the
// solid angle of the whole window, which the occlusion query's equal weights share out.
#pragma once
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
#include <cmath>

namespace gib::rt::gpu {
using std::atan;
using std::sqrt;
#endif

// One bit of the coverage image per sample: at most 8 (an 8-bit image, as the paper's).
const int kMaxSamplesPerPixel = 8;

// std430, binding kCoverageTrianglesBinding: the light's triangles, then the occluders', three
// vec4 (xyz, w unused) per triangle, world space.
const int kCoverageTrianglesBinding = kTechniqueFirstStorageBinding + 0;

// The technique's coverage images (a layer per G-buffer point of the batch), read by the weighting
// pass; its work groups, one per point, share the point's pixels among their invocations.
const int kCoverageUnit = kTechniqueFirstUnit + 0;
const int kWeighGroupSize = 64;

// A 32-bit integer hash with full avalanche (Wellons' "lowbias32"): the same bits in C++ and GLSL.
GIB_SHARED_FUNCTION uint coverageHash(uint x) {
  x ^= x >> 16u;
  x *= 0x7feb352du;
  x ^= x >> 15u;
  x *= 0x846ca68bu;
  x ^= x >> 16u;
  return x;
}

// The top 24 bits of a hash as a float in [0, 1) (exact in both languages).
GIB_SHARED_FUNCTION float coverageUnitFloat(uint h) {
  return float(h >> 8u) * (1.0f / 16777216.0f);
}

// Strata of a pixel for n jittered samples: 1×1, 2×2 or 4×2 (columns × rows); the paper's
// "portion of the surface of the pixel that is regularly subdivided".
GIB_SHARED_FUNCTION int coverageStrataColumns(int n) {
  return n >= 8 ? 4 : (n >= 4 ? 2 : 1);
}

// Position of jittered sample k (of n) inside pixel `pixel` of the image drawn for point `point`,
// in pixel units from the pixel's lower left corner: uniform in stratum k. `samples` 0 means the
// regular scheme (one sample at the pixel centre).
GIB_SHARED_FUNCTION vec2 coverageSampleOffset(uint seed, uint point, uint pixel, int k,
                                              int samples) {
  if (samples == 0) return vec2(0.5f, 0.5f);
  int columns = coverageStrataColumns(samples);
  int rows = samples / columns;
  uint h = coverageHash(seed ^ coverageHash(point ^ coverageHash(pixel * 8u + uint(k))));
  float u = coverageUnitFloat(h);
  float v = coverageUnitFloat(coverageHash(h));
  return vec2((float(k % columns) + u) / float(columns), (float(k / columns) + v) / float(rows));
}

// The solid angle of the rectangle [0, a] × [0, b] in a plane at distance h, seen from the point
// over its corner; odd in a and in b, so that corners combine with signs.
GIB_SHARED_FUNCTION float cornerSolidAngle(float a, float b, float h) {
  return atan(a * b / (h * sqrt(h * h + a * a + b * b)));
}

// The solid angle of a point's window [u0, u1] × [v0, v1] (window = (u0, v0, u1, v1)) in the
// light's plane at distance d.
GIB_SHARED_FUNCTION float windowSolidAngle(vec4 window, float d) {
  return cornerSolidAngle(window.z, window.w, d) - cornerSolidAngle(window.x, window.w, d) -
         cornerSolidAngle(window.z, window.y, d) + cornerSolidAngle(window.x, window.y, d);
}

#ifdef __cplusplus
static_assert(kCoverageTrianglesBinding <
              kTechniqueFirstStorageBinding + kTechniqueStorageBindingCount);
}  // namespace gib::rt::gpu
#endif
