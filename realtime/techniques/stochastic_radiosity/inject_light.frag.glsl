// First-bounce injection (prepare time): the direct light of one spot or directional light
// sample, reflected by each atlas texel's front side (f = ρ/π; the technique is diffuse-only),
// shadow-mapped with `direct`'s shadow maps, added into the source map. Shooting then treats it
// like emission: the texel re-radiates what it reflects of the point light, so the stochastic
// iteration computes the bounces after the first.
#include "realtime/atlas/atlas_maps.glsl"
#include "realtime/lighting/shadow_lookup.glsl"
#include "realtime/lighting/light_irradiance.glsl"
#include "realtime/gpu_scene/brdf.glsl"

layout(location = 0) out vec4 o_radiance;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 position = texelFetch(u_atlas_position, texel, 0);
  if (position.w == 0.0) discard;
  vec3 p = position.xyz, n = texelFetch(u_atlas_normal, texel, 0).xyz;
  vec3 wi, irradiance;
  if (!lightSampleIrradiance(p, wi, irradiance)) discard;
  float cos_surface = dot(n, wi);
  if (cos_surface <= 0.0) discard;
  vec3 brdf = texelFetch(u_atlas_albedo, texel, 0).rgb * kInvPi;
  o_radiance = vec4(brdf * irradiance * (cos_surface * lightVisibility(p, n)), 0.0);
}
