// The visibility network V (book §9.6.2): from particle p's centre along ω_i, the particle whose
// sphere the line crosses with the nearest centre ahead (ties by index), and its opacity along
// that line, 1 − exp(−optical depth of its whole chord). The book bins orthographic projections;
// the line test is the same relation without a window's resolution.
#include "realtime/particles/particle_medium.glsl"
#include "realtime/techniques/illumination_network/network.glsl"

layout(std430, binding = kVisibilityBinding) writeonly buffer Visibility {
  NetworkLink links[];
};

void main() {
  int p = int(gl_GlobalInvocationID.x);
  int i = int(gl_GlobalInvocationID.y);
  if (p >= u_count) return;
  vec3 origin = particles[p].centre_radius.xyz;
  vec3 omega = directions[i].xyz;
  int best = -1;
  float best_t = 3.0e38, best_d2 = 0.0;
  for (int q = 0; q < u_count; ++q) {
    if (q == p) continue;
    vec4 sphere = particles[q].centre_radius;
    vec3 v = sphere.xyz - origin;
    float t = dot(v, omega);
    if (t <= 0.0 || t >= best_t) continue;
    float d2 = dot(v, v) - t * t;
    if (d2 >= sphere.w * sphere.w) continue;
    best = q;
    best_t = t;
    best_d2 = d2;
  }
  float opacity = 0.0;
  if (best >= 0) {
    vec4 sphere = particles[best].centre_radius;
    float depth = chordOpticalDepth(particles[best].density.x, sphere.w, sqrt(max(best_d2, 0.0)),
                                    -sphere.w, sphere.w);
    opacity = 1.0 - exp(-depth);
  }
  links[p * u_direction_count + i] = NetworkLink(best, opacity);
}
