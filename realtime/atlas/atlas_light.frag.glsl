// The light of a batch of spot, point or directional light samples reflected by each atlas
// texel's front side (f = ρ/π: the atlas techniques are diffuse-only), shadow-mapped with the shared shadow
// maps, for additive blending into an atlas-sized target. Stochastic radiosity injects its first
// bounce this way (prepare time; shooting then treats it like emission); light path maps connect
// each virtual light to every exit texel it sees this way (book §8.4.1).
#include "realtime/atlas/atlas_maps.glsl"
#include "realtime/lighting/shadowed_irradiance.glsl"
#include "realtime/gpu_scene/brdf.glsl"

layout(location = 0) out vec4 o_radiance;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 position = texelFetch(u_atlas_position, texel, 0);
  if (position.w == 0.0) discard;
  vec3 irradiance = batchIrradiance(position.xyz, texelFetch(u_atlas_normal, texel, 0).xyz);
  o_radiance = vec4(texelFetch(u_atlas_albedo, texel, 0).rgb * kInvPi * irradiance, 0.0);
}
