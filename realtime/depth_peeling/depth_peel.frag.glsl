// One peeling pass (book §10.4): a fragment no farther than the surface the previous pass kept at
// its pixel (plus the epsilon of depth_peeler.h) is peeled away; of the others the depth test
// keeps the nearest. Writes the layer's record and, for the next pass, its depth.
#include "realtime/depth_peeling/depth_peeling_shared.h"

layout(binding = kPeelPreviousDepthUnit) uniform sampler2D u_previous_depth;
uniform int u_first;
uniform float u_epsilon;
in vec2 v_atlas_uv;
in float v_depth;
flat in float v_facing;
layout(location = 0) out vec4 o_layer;
layout(location = 1) out float o_depth;

void main() {
  if (u_first == 0) {
    float last_depth = texelFetch(u_previous_depth, ivec2(gl_FragCoord.xy), 0).r;
    if (v_depth <= last_depth + u_epsilon) discard;
  }
  o_layer = vec4(v_atlas_uv, v_facing, v_depth);
  o_depth = v_depth;
}
