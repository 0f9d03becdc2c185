// Second half of an iteration: the incoming radiance of particle p from direction ω_i gathered
// along its chain in V (p sees vp, vp sees the next, ...): I[p, i] = Σ_j (Π_{k<j} (1 − α_k)) α_j J[j, i]
// plus the sky times the whole chain's transmittance. The book advances one link per iteration
// ((1 − α)·I[vp, i] of the previous step); walking the chain instead makes iteration k hold
// exactly the paths of up to k + 1 scattering events, whatever the medium's optical depth.
#include "realtime/particles/particle_medium.glsl"
#include "realtime/techniques/illumination_network/network.glsl"

layout(std430, binding = kVisibilityBinding) readonly buffer Visibility {
  NetworkLink links[];
};
layout(std430, binding = kSourceBinding) readonly buffer Source {
  vec4 source[];
};
layout(std430, binding = kIncomingRadianceBinding) writeonly buffer Incoming {
  vec4 incoming[];  // rgb: radiance, w: the chain's transmittance
};

void main() {
  int p = int(gl_GlobalInvocationID.x);
  int i = int(gl_GlobalInvocationID.y);
  if (p >= u_count) return;
  vec3 radiance = vec3(0.0);
  float transmittance = 1.0;
  int current = p;
  // Centres strictly advance along ω_i, so a chain has at most N links.
  for (int step = 0; step < u_count; ++step) {
    NetworkLink link = links[current * u_direction_count + i];
    if (link.particle < 0) {
      radiance += transmittance * u_sky;
      break;
    }
    radiance += transmittance * link.opacity * source[link.particle * u_direction_count + i].rgb;
    transmittance *= 1.0 - link.opacity;
    current = link.particle;
  }
  incoming[p * u_direction_count + i] = vec4(radiance, transmittance);
}
