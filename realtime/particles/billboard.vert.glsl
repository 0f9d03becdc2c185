// Particle k of the back-to-front order drawn as a screen-aligned quad that holds its sphere's
// projection (the book sends particles as quads and takes their spherical shape into account per
// fragment, §9.3.1); a triangle strip of four corners per instance.
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/gpu_scene/screen_rect_shared.h"
#include "realtime/particles/particle_medium.glsl"

layout(std430, binding = kParticleOrderBinding) readonly buffer Order {
  uint order[];
};
flat out int v_particle;

void main() {
  int p = int(order[gl_InstanceID]);
  vec4 sphere = particles[p].centre_radius;
  vec4 rect = sphereScreenRect(camera.view, camera.projection, sphere.xyz, sphere.w);
  vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
  gl_Position = vec4(mix(rect.xy, rect.zw, corner), 0.0, 1.0);
  v_particle = p;
}
