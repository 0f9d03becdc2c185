// The light samples of one batch as the shading passes read them (a uniform block, std140): a
// batch's shadow maps are the layers of one array texture, sample k's in layer k (cube map
// arrays: layer-faces 6k..6k+5), so one pass lights a point with every sample of the batch.
#pragma once
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

namespace gib::rt::gpu {
using glm::dot;
using glm::inversesqrt;
using glm::max;
using glm::pow;
#endif

// Samples per batch at most (the uniform block's array; 112 bytes each, within the 16 KiB every
// GL 4.5 implementation offers).
const int kMaxLightBatch = 32;

struct GpuLightSample {
  // xyz point sample's position; w a point sample's term added to the squared distance, a
  // directional sample's cap half-angle (radians, 0 but for environment_shadows' cells:
  // cell_reflectivity_shared.h)
  vec4 position;
  vec4 axis;             // xyz spot axis or direction of travel (unit); w cos of the cone
  vec4 intensity;        // rgb intensity (irradiance for directional); w falloff exponent
  mat4 view_projection;  // directional: world to the orthographic map's clip space
};

// What point sample `s` delivers at p, on a plane facing it: rgb the irradiance, w 1 inside a
// spot's cone and 0 outside (no light at all). The shading passes (light_irradiance.glsl) and the
// CPU irradiance cache's shadow rays both light with it.
GIB_SHARED_FUNCTION vec4 pointSampleIrradiance(GpuLightSample s, vec3 p) {
  vec3 to_light = vec3(s.position) - p;
  float distance_squared = dot(to_light, to_light);
  vec3 wi = to_light * inversesqrt(distance_squared);
  float cos_axis = dot(-wi, vec3(s.axis));
  if (cos_axis < s.axis.w) return vec4(0.0f);
  float falloff = s.intensity.w == 0.0f ? 1.0f : pow(max(cos_axis, 0.0f), s.intensity.w);
  // position.w: 0 for a light that is a point; a virtual light that stands for a patch (light
  // path maps) gives the patch's area over π, which keeps its irradiance on a receiver beside it
  // finite (the on-axis irradiance of a disk of that area).
  return vec4(vec3(s.intensity) * (falloff / (distance_squared + s.position.w)), 1.0f);
}

// One layer the shadow pass draws the scene into, per instance of its one draw (layered
// rendering): a cube face of a point sample, or a directional sample's map.
const int kMaxShadowFaces = 6 * kMaxLightBatch;
struct ShadowFace {
  mat4 view_projection;  // world to the face's clip space
  // x: layer (cube maps: 6·slot + face), y: the sample's slot in the batch; z, w: the texel
  // columns and rows outside which the face holds nothing but the cleared value (what lies
  // behind a point sample's plane is not drawn), packed by packTexelRange; the variance filter
  // works inside them.
  ivec4 layer_slot;
};

// A half-open range of texels [first, end) in one int: first in the low 16 bits, end in the
// high ones (maps are at most 4096 texels a side).
GIB_SHARED_FUNCTION int packTexelRange(int first, int end) {
  return first | (end << 16);
}
GIB_SHARED_FUNCTION ivec2 unpackTexelRange(int range) {
  return ivec2(range & 0xffff, range >> 16);
}

#ifdef __cplusplus
static_assert(sizeof(GpuLightSample) == 112, "std140: three vec4 and a mat4");
static_assert(sizeof(ShadowFace) * kMaxShadowFaces <= 16384, "GL 4.5's smallest uniform block");
}  // namespace gib::rt::gpu
#endif
