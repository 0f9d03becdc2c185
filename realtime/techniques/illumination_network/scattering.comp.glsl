// First half of an iteration (book (9.5)): each particle's radiance towards −ω_i per unit opacity,
// J[p, i] = E[p, i] + a·Σ_d I[p, d] W[d, i], with W[d, i] = p(ω_d·ω_i) / Σ_d' p(ω_d'·ω_i) the
// phase function between the network's directions (the book's 4π/D weights, normalised so that
// the discrete phase function sums to one and a lossless medium conserves energy exactly). A
// work group serves one particle: its D incoming radiances are read once into shared memory.
#include "realtime/techniques/illumination_network/illumination_network_shared.h"

layout(local_size_x = kParticleGroupSize) in;
layout(std430, binding = kIncomingRadianceBinding) readonly buffer Incoming {
  vec4 incoming[];
};
layout(std430, binding = kEmissionBinding) readonly buffer Emission {
  vec4 emission[];
};
layout(std430, binding = kSourceBinding) writeonly buffer Source {
  vec4 source[];
};
layout(binding = kPhaseMatrixUnit) uniform sampler2D u_phase_matrix;  // W[d, i] at (i, d)
uniform int u_direction_count;  // D
uniform vec3 u_albedo;

shared vec3 particle_incoming[kMaxNetworkDirections];

void main() {
  int i = int(gl_GlobalInvocationID.x);
  int p = int(gl_WorkGroupID.y);
  int row = p * u_direction_count;
  for (int d = int(gl_LocalInvocationID.x); d < u_direction_count; d += kParticleGroupSize)
    particle_incoming[d] = incoming[row + d].rgb;
  barrier();
  if (i >= u_direction_count) return;
  vec3 sum = vec3(0.0);
  for (int d = 0; d < u_direction_count; ++d)
    sum += texelFetch(u_phase_matrix, ivec2(i, d), 0).r * particle_incoming[d];
  source[row + i] = vec4(emission[row + i].rgb + u_albedo * sum, 0.0);
}
