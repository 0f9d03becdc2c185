// The indirect light of every exit point (atlas texel) for the current lights: the selected
// clusters' panes weighted by their clusters' irradiance and summed (book §8.4.1; the weights
// carry the 1/N of the entry points' average, the panes the area S of their density 1/S).
#include "realtime/techniques/light_path_map/light_path_map_shared.h"

layout(std430, binding = kSelectedPanesBinding) readonly buffer SelectedPanes {
  SelectedPane selected[];
};
layout(binding = kPanesUnit) uniform sampler2DArray u_panes;
uniform int u_selected_count;
layout(location = 0) out vec4 o_indirect;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec3 sum = vec3(0.0);
  for (int k = 0; k < u_selected_count; ++k)
    sum += selected[k].weight * texelFetch(u_panes, ivec3(texel, selected[k].layer), 0).rgb;
  o_indirect = vec4(sum, 1.0);
}
