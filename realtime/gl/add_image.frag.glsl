// Adds an image of the frame's size into the frame pixel for pixel (with additive blending): a
// technique's camera view of its own light (light path maps' indirect light, the obscurances'
// ambient term), drawn into a target of its own for its depth test, composited onto the direct
// light.
#include "realtime/gl/binding_plan_shared.h"

layout(binding = kAddedImageUnit) uniform sampler2D u_added;
layout(location = 0) out vec4 o_radiance;

void main() {
  o_radiance = vec4(texelFetch(u_added, ivec2(gl_FragCoord.xy), 0).rgb, 0.0);
}
