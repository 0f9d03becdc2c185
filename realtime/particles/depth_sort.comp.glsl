// Back-to-front order of the particles as seen from the eye, by rank: a particle's place is the
// number of particles farther from the eye (ties by index), so the order is the same on any GPU.
// N² comparisons, in one pass with no synchronisation: a few million for the book's thousand.
#include "realtime/particles/particle_medium.glsl"

layout(local_size_x = kParticleGroupSize) in;
layout(std430, binding = kParticleOrderBinding) writeonly buffer Order {
  uint order[];
};
uniform int u_count;
uniform vec3 u_eye;

void main() {
  int p = int(gl_GlobalInvocationID.x);
  if (p >= u_count) return;
  vec3 e = particles[p].centre_radius.xyz - u_eye;
  float key = dot(e, e);
  int rank = 0;
  for (int q = 0; q < u_count; ++q) {
    vec3 f = particles[q].centre_radius.xyz - u_eye;
    float other = dot(f, f);
    if (other > key || (other == key && q < p)) ++rank;
  }
  order[rank] = uint(p);
}
