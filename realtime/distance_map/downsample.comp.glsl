// A distance map downsampled (book §7.3): texel (i, j) of an M × M face averages the radiance and
// the distance of the B × B texels of the N × N face it covers, B = N/M, so that each texel of
// the small map stands for the surface its texels see: an area light with their mean radiance
// at their mean distance.
#include "realtime/distance_map/distance_map_shared.h"

layout(local_size_x = kDistanceMapGroupSize, local_size_y = kDistanceMapGroupSize) in;

layout(binding = kImageSourceUnit, rgba32f) uniform readonly imageCubeArray u_source;
layout(binding = kImageDestinationUnit, rgba32f) uniform writeonly imageCubeArray u_destination;

uniform int u_block;  // B
uniform int u_size;   // M

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  if (texel.x >= u_size || texel.y >= u_size) return;
  vec4 sum = vec4(0.0);
  for (int j = 0; j < u_block; ++j)
    for (int i = 0; i < u_block; ++i)
      sum += imageLoad(u_source, ivec3(texel.x * u_block + i, texel.y * u_block + j, texel.z));
  imageStore(u_destination, texel, sum / float(u_block * u_block));
}
