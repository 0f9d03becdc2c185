// Ward's interpolation from the splatted sums, E = Σ w·E_k / Σ w, reflected: ρ/π · E added to the
// frame (pixels no record reaches add nothing).
#include "realtime/techniques/irradiance_cache_splatting/irradiance_cache_splatting_shared.h"

layout(binding = kSplatSumsUnit) uniform sampler2D u_sums;
layout(binding = kSplatAlbedoUnit) uniform sampler2D u_albedo;
layout(location = 0) out vec4 o_radiance;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 sums = texelFetch(u_sums, pixel, 0);
  vec3 albedo = texelFetch(u_albedo, pixel, 0).rgb;
  o_radiance = sums.a > 0.0 ? vec4(albedo * (0.31830988618 / sums.a) * sums.rgb, 0.0) : vec4(0.0);
}
