// One direction of the separable box filter over a batch's variance shadow maps (the book's 5×5
// texel filter, §4.1.3, Fig. 4.5), every layer in one dispatch. Cube maps are filtered face by
// face; taps clamp at face edges.
#include "realtime/lighting/lighting_shared.h"

layout(local_size_x = kVsmBlurGroupSize, local_size_y = kVsmBlurGroupSize, local_size_z = 1) in;
#ifdef POINT_LIGHT
layout(rg32f, binding = kImageSourceUnit) uniform readonly imageCubeArray u_source;
layout(rg32f, binding = kImageDestinationUnit) uniform writeonly imageCubeArray u_destination;
#else
layout(rg32f, binding = kImageSourceUnit) uniform readonly image2DArray u_source;
layout(rg32f, binding = kImageDestinationUnit) uniform writeonly image2DArray u_destination;
#endif
#define COORD(xy) ivec3(xy, int(gl_GlobalInvocationID.z))
uniform ivec2 u_step;  // (1,0) then (0,1)
uniform int u_radius;  // 2 for the 5-texel box
uniform int u_size;

void main() {
  ivec2 xy = ivec2(gl_GlobalInvocationID.xy);
  if (xy.x >= u_size || xy.y >= u_size) return;
  vec2 sum = vec2(0.0);
  for (int k = -u_radius; k <= u_radius; ++k)
    sum += imageLoad(u_source, COORD(clamp(xy + k * u_step, ivec2(0), ivec2(u_size - 1)))).rg;
  imageStore(u_destination, COORD(xy), vec4(sum / float(2 * u_radius + 1), 0.0, 0.0));
}
