// Ward's irradiance cache as both irradiance cache techniques read it (course notes 001): the
// record, the weighting function, a record's extrapolated irradiance and its zone of influence on
// the screen. Written once for the CPU cache's octree lookups and the GPU's splatting, so the two
// interpolate the same records to the same values.
#pragma once
#include "realtime/gl/host_device_shared.h"
#include "realtime/gpu_scene/screen_rect_shared.h"

#ifdef __cplusplus
#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

namespace gib::rt::gpu {
using glm::cross;
using glm::dot;
using glm::length;
using glm::max;
using glm::min;
using glm::normalize;
using glm::sqrt;
#endif

// A record (Ward 1988, gradients Ward & Heckbert 1992), std430: position P_k and the harmonic mean
// distance R_k to the surfaces its hemisphere sees, normal n_k, irradiance E_k, and per colour
// channel c the rotation and translation gradients of E_k.
struct IrradianceRecord {
  vec4 position_radius;  // xyz P_k, w R_k
  vec4 normal;           // xyz n_k (on the viewer's side), w unused
  vec4 irradiance;       // rgb E_k, w unused
  vec4 rotation[3];      // xyz ∇r E_k of channel c
  vec4 translation[3];   // xyz ∇t E_k of channel c
};

// The weight's denominator never falls below this: at the record itself it is zero.
const float kMinWeightDenominator = 1e-6f;

// Ward's weighting function, w_k(P) = 1 / (|P − P_k| / R_k + √(1 − n·n_k)). A record contributes
// to P where w_k(P) > 1/a (a: the cache's accuracy).
GIB_SHARED_FUNCTION float recordWeight(IrradianceRecord record, vec3 p, vec3 n) {
  float d = length(p - vec3(record.position_radius)) / record.position_radius.w +
            sqrt(max(1.0f - dot(n, vec3(record.normal)), 0.0f));
  return 1.0f / max(d, kMinWeightDenominator);
}

// The record's irradiance extrapolated to P with normal n (Ward & Heckbert):
// E_k + (n_k × n)·∇r E_k + (P − P_k)·∇t E_k per channel, never negative.
GIB_SHARED_FUNCTION vec3 recordIrradiance(IrradianceRecord record, vec3 p, vec3 n) {
  vec3 axis = cross(vec3(record.normal), n);
  vec3 offset = p - vec3(record.position_radius);
  vec3 e = vec3(record.irradiance);
  for (int c = 0; c < 3; ++c)
    e[c] += dot(axis, vec3(record.rotation[c])) + dot(offset, vec3(record.translation[c]));
  return max(e, vec3(0.0f));
}

// Duff et al. 2017's branchless orthonormal basis around a unit normal: tangent and bitangent,
// (t, b, n) right-handed.
GIB_SHARED_FUNCTION vec3 basisTangent(vec3 n) {
  float s = n.z >= 0.0f ? 1.0f : -1.0f;
  float a = -1.0f / (s + n.z);
  return vec3(1.0f + s * n.x * n.x * a, s * n.x * n.y * a, -s * n.x);
}
GIB_SHARED_FUNCTION vec3 basisBitangent(vec3 n) {
  float s = n.z >= 0.0f ? 1.0f : -1.0f;
  float a = -1.0f / (s + n.z);
  return vec3(n.x * n.y * a, s + n.y * n.y * a, -n.y);
}

#ifdef __cplusplus
static_assert(sizeof(IrradianceRecord) == 9 * 16, "std430 struct IrradianceRecord: nine vec4");
}  // namespace gib::rt::gpu
#endif
