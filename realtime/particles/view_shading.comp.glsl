// Each particle's radiance towards the eye per unit opacity (the in-scattering term of the book's
// (9.4) over α): a·[Σ_lights p(ω_l·v) E_l T_l + Σ_d L_in(ω_d) p(−ω_d·v) / Σ_d p(−ω_d·v)], with v the
// direction from the particle to the eye. The incoming radiance L_in of the D directions is the
// sky through the volume's transmittance (spherical billboards: single scattering) or the
// illumination network's incoming radiance; the sum is normalised by the discrete phase so that a
// uniform L_in scatters exactly L_in.
#include "realtime/particles/particle_medium.glsl"

layout(local_size_x = kParticleGroupSize) in;
layout(std430, binding = kTransmittanceBinding) readonly buffer Transmittance {
  float transmittance[];  // [particle × u_stride + light, then sky directions]
};
layout(std430, binding = kSphereDirectionsBinding) readonly buffer Directions {
  vec4 directions[];  // ω_d, towards where the light comes from
};
layout(std430, binding = kParticleSourceBinding) writeonly buffer Source {
  vec4 source[];
};
layout(std430, binding = kIncomingRadianceBinding) readonly buffer Incoming {
  vec4 incoming[];  // [particle × D + d], the network's incoming radiance
};
uniform int u_count;
uniform int u_stride;           // transmittances per particle
uniform int u_direction_count;  // D
uniform bool u_sky_through_transmittance;
uniform vec3 u_eye;

void main() {
  int p = int(gl_GlobalInvocationID.x);
  if (p >= u_count) return;
  vec3 v = normalize(u_eye - particles[p].centre_radius.xyz);
  vec3 direct = vec3(0.0);
  for (int l = 0; l < u_light_count; ++l)
    direct += phase(dot(u_light_direction[l], v)) * u_light_irradiance[l] *
              transmittance[p * u_stride + l];
  vec3 scattered = vec3(0.0);
  float weight = 0.0;
  for (int d = 0; d < u_direction_count; ++d) {
    float w = phase(-dot(directions[d].xyz, v));
    vec3 radiance = u_sky_through_transmittance
                        ? u_sky * transmittance[p * u_stride + u_light_count + d]
                        : incoming[p * u_direction_count + d].rgb;
    scattered += w * radiance;
    weight += w;
  }
  if (weight > 0.0) scattered /= weight;
  source[p] = vec4(u_albedo * (direct + scattered), 1.0);
}
