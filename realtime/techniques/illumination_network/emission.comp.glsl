// The emission array E (book §9.6.2): per particle p and direction i, the directional lights'
// radiance p scatters towards −ω_i (to the particles that see it in direction i) per unit
// opacity, a·Σ_l p(d_l·(−ω_i)) E_l T_l, with T_l the volume's transmittance from p to light l.
#include "realtime/particles/particle_medium.glsl"
#include "realtime/techniques/illumination_network/network.glsl"

layout(std430, binding = kTransmittanceBinding) readonly buffer Transmittance {
  float transmittance[];  // [particle × lights + light]
};
layout(std430, binding = kEmissionBinding) writeonly buffer Emission {
  vec4 emission[];
};

void main() {
  int p = int(gl_GlobalInvocationID.x);
  int i = int(gl_GlobalInvocationID.y);
  if (p >= u_count) return;
  vec3 towards_receiver = -directions[i].xyz;
  vec3 e = vec3(0.0);
  for (int l = 0; l < u_light_count; ++l)
    e += phase(dot(u_light_direction[l], towards_receiver)) * u_light_irradiance[l] *
         transmittance[p * u_light_count + l];
  emission[p * u_direction_count + i] = vec4(u_albedo * e, 0.0);
}
