// Adds the camera view of the indirect light into the frame (additive blending), pixel for pixel.
#include "realtime/techniques/light_path_map/light_path_map_shared.h"

layout(binding = kIndirectUnit) uniform sampler2D u_indirect;
layout(location = 0) out vec4 o_radiance;

void main() {
  o_radiance = vec4(texelFetch(u_indirect, ivec2(gl_FragCoord.xy), 0).rgb, 0.0);
}
