// The weights of a frame (book §8.4.1, "rendering to a one-dimensional texture of weights"): the
// irradiance the current batch of light samples delivers to each entry point, on its front side,
// with visibility from the samples' shadow maps (those the direct light was just drawn with). One
// fragment per entry point; the batches add up by blending.
#include "realtime/techniques/light_path_map/light_path_map_shared.h"
#include "realtime/lighting/shadowed_irradiance.glsl"

layout(binding = kEntryPositionUnit) uniform sampler2D u_entry_position;
layout(binding = kEntryNormalUnit) uniform sampler2D u_entry_normal;
layout(location = 0) out vec4 o_irradiance;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 position = texelFetch(u_entry_position, texel, 0);
  if (position.w == 0.0) discard;
  o_irradiance =
      vec4(batchIrradiance(position.xyz, texelFetch(u_entry_normal, texel, 0).xyz), 0.0);
}
