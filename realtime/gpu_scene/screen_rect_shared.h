// Screen-space bounds of world-space shapes, read by C++ (placement on the CPU) and GLSL (splats'
// vertex shaders).
#pragma once
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
#include <glm/common.hpp>

namespace gib::rt::gpu {
using glm::max;
using glm::min;
#endif

// The screen rectangle (normalised device coordinates: x0, y0, x1, y1) that holds the projection
// of a sphere: the projected corners of its bounding box in view space, or the whole screen when
// the box reaches behind the eye. Splats draw it as a quad (an irradiance record's zone of
// influence, a particle's spherical billboard).
GIB_SHARED_FUNCTION vec4 sphereScreenRect(mat4 view, mat4 projection, vec3 centre, float radius) {
  vec3 c = vec3(view * vec4(centre, 1.0f));
  vec2 lo = vec2(1.0f), hi = vec2(-1.0f);
  for (int i = 0; i < 8; ++i) {
    vec3 corner = c + radius * vec3((i & 1) != 0 ? 1.0f : -1.0f, (i & 2) != 0 ? 1.0f : -1.0f,
                                    (i & 4) != 0 ? 1.0f : -1.0f);
    vec4 clip = projection * vec4(corner, 1.0f);
    if (clip.w <= 1e-6f * radius) return vec4(-1.0f, -1.0f, 1.0f, 1.0f);
    vec2 ndc = vec2(clip) / clip.w;
    lo = min(lo, ndc);
    hi = max(hi, ndc);
  }
  return vec4(max(lo, vec2(-1.0f)), min(hi, vec2(1.0f)));
}

#ifdef __cplusplus
}  // namespace gib::rt::gpu
#endif
