// The materials of docs/architecture.md, evaluated exactly as the reference does
// (reference/bsdf.cpp): Lambert f = ρd/π; normalised modified Phong adds ρs·(n+2)/(2π)·cosⁿα, α
// between the mirror direction of ωo and ωi. `n` faces the side of ωo. Shared by the shading
// passes (brdf.glsl) and the CPU irradiance cache.
#pragma once
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

namespace gib::rt::gpu {
using glm::dot;
using glm::pow;
#endif

const float kInvPi = 0.31830988618379067f;

GIB_SHARED_FUNCTION vec3 evaluateBrdf(vec3 diffuse, vec3 specular, float exponent, bool phong,
                                      vec3 n, vec3 wo, vec3 wi) {
  if (dot(n, wi) <= 0.0f) return vec3(0.0f);
  vec3 f = diffuse * kInvPi;
  if (phong) {
    float c = dot(2.0f * dot(n, wo) * n - wo, wi);
    if (c > 0.0f) f += specular * ((exponent + 2.0f) * 0.5f * kInvPi * pow(c, exponent));
  }
  return f;
}

#ifdef __cplusplus
}  // namespace gib::rt::gpu
#endif
