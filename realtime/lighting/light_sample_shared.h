// The light samples of one batch as the shading passes read them (a uniform block, std140): a
// batch's shadow maps are the layers of one array texture, sample k's in layer k (cube map
// arrays: layer-faces 6k..6k+5), so one pass lights a point with every sample of the batch.
#pragma once
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

// Samples per batch at most (the uniform block's array; 112 bytes each, within the 16 KiB every
// GL 4.5 implementation offers).
const int kMaxLightBatch = 32;

struct GpuLightSample {
  vec4 position;         // xyz point sample's position; w added to the squared distance
  vec4 axis;             // xyz spot axis or direction of travel (unit); w cos of the cone
  vec4 intensity;        // rgb intensity (irradiance for directional); w falloff exponent
  mat4 view_projection;  // directional: world to the orthographic map's clip space
};

// One layer the shadow pass draws the scene into, per instance of its one draw (layered
// rendering): a cube face of a point sample, or a directional sample's map.
const int kMaxShadowFaces = 6 * kMaxLightBatch;
struct ShadowFace {
  mat4 view_projection;  // world to the face's clip space
  ivec4 layer_slot;      // x: layer (cube maps: 6·slot + face), y: the sample's slot in the batch
};

#ifdef __cplusplus
static_assert(sizeof(GpuLightSample) == 112, "std140: three vec4 and a mat4");
static_assert(sizeof(ShadowFace) * kMaxShadowFaces <= 16384, "GL 4.5's smallest uniform block");
}  // namespace gib::rt::gpu
#endif
