// The obscurances map from the bundle sums (obscurances_technique.h, "Normalisation"): a patch of
// area A is crossed by A·|cos θ|/s² rays of a bundle on average, and |cos θ| averages 1/2 over
// uniform directions, so W = (2 s² / (N A))·Σ samples is unbiased for the patch's mean obscurance.
// A gutter texel shows the covered texel whose sample point it copies.
#include "realtime/atlas/atlas_maps.glsl"
#include "realtime/techniques/obscurances/obscurances_shared.h"

layout(binding = kObscuranceSumsUnit) uniform sampler2D u_sums;
layout(binding = kObscuranceSourceUnit) uniform sampler2D u_source;
uniform float u_scale;  // 2 s² / N
layout(location = 0) out vec4 o_obscurance;

void main() {
  vec4 source = texelFetch(u_source, ivec2(gl_FragCoord.xy), 0);
  ivec2 texel = ivec2(source.xy);
  float area = texelFetch(u_atlas_normal, texel, 0).w;
  vec4 sums = texelFetch(u_sums, texel, 0);
  vec3 w = source.w > 0.0 && area > 0.0 ? sums.rgb * (u_scale / area) : vec3(0.0);
  o_obscurance = vec4(w, sums.a);
}
