// First-bounce injection (prepare time): the direct light of one spot or directional light
// sample, reflected by each atlas texel's front side (f = ρ/π; the technique is diffuse-only),
// shadow-mapped with `direct`'s shadow maps, added into the source map. Shooting then treats it
// like emission: the texel re-radiates what it reflects of the point light, so the stochastic
// iteration computes the bounces after the first.
#include "atlas/atlas_maps.glsl"
#include "techniques/direct/shadow_lookup.glsl"

uniform vec3 u_light_intensity;
uniform float u_cos_cone;
uniform float u_exponent;
layout(location = 0) out vec4 o_radiance;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 position = texelFetch(u_atlas_position, texel, 0);
  if (position.w == 0.0) discard;
  vec3 p = position.xyz, n = texelFetch(u_atlas_normal, texel, 0).xyz;
#ifdef POINT_LIGHT
  vec3 to_light = u_light_position - p;
  float distance_squared = dot(to_light, to_light);
  vec3 wi = to_light * inversesqrt(distance_squared);
  float cos_axis = dot(-wi, u_light_axis);
  if (cos_axis < u_cos_cone) discard;
  float falloff = u_exponent == 0.0 ? 1.0 : pow(max(cos_axis, 0.0), u_exponent);
  vec3 irradiance = u_light_intensity * (falloff / distance_squared);
#else
  vec3 wi = -u_light_axis;
  vec3 irradiance = u_light_intensity;
#endif
  float cos_surface = dot(n, wi);
  if (cos_surface <= 0.0) discard;
  vec3 brdf = texelFetch(u_atlas_albedo, texel, 0).rgb / 3.14159265358979;
  o_radiance = vec4(brdf * irradiance * (cos_surface * lightVisibility(p, n)), 0.0);
}
