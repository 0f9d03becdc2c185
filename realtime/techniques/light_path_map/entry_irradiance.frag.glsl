// The weights of a frame (book §8.4.1, "rendering to a one-dimensional texture of weights"): the
// irradiance the current light sample delivers to each entry point, on its front side, with
// visibility from the sample's shadow map (the one the direct light was just drawn with). One
// fragment per entry point; the samples add up by blending.
#include "realtime/techniques/light_path_map/light_path_map_shared.h"
#include "realtime/lighting/shadowed_irradiance.glsl"

layout(binding = kEntryPositionUnit) uniform sampler2D u_entry_position;
layout(binding = kEntryNormalUnit) uniform sampler2D u_entry_normal;
layout(location = 0) out vec4 o_irradiance;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 position = texelFetch(u_entry_position, texel, 0);
  if (position.w == 0.0) discard;
  vec3 wi, irradiance;
  if (!shadowedIrradiance(position.xyz, texelFetch(u_entry_normal, texel, 0).xyz, wi, irradiance))
    discard;
  o_irradiance = vec4(irradiance, 0.0);
}
