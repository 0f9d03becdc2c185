// One bit per sample of the pixel: set where the sample lies inside the triangle (§4.2.2). The
// caller combines the bits with the framebuffer's logic operation: OR for the light's triangles,
// AND NOT for the occluders (whose depth test keeps only those in front of the light).
#include "realtime/techniques/jittered_light_sampling/jittered_light_sampling_shared.h"

uniform int u_samples;  // 0: the regular scheme (pixel centres); else jittered, 1..8 per pixel
uniform uint u_seed;
uniform int u_size;
flat in vec2 v_a;
flat in vec2 v_b;
flat in vec2 v_c;
flat in vec3 v_depth_plane;
flat in uint v_point;
layout(location = 0) out uint o_mask;

float edge(vec2 a, vec2 b, vec2 p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// Whether p is on the inner side of the directed edge a → b of a counter-clockwise triangle. A
// sample on an edge that two triangles share must count for exactly one of them (two would count
// a light pixel twice in the occlusion query, none would leave a hole): the edge function is
// evaluated from the same end for both directions, so both triangles see the same value with
// opposite signs, and a tie belongs to edges pointing up, or left when horizontal.
bool inside(vec2 a, vec2 b, vec2 p) {
  bool forward = a.x < b.x || (a.x == b.x && a.y < b.y);
  float e = forward ? edge(a, b, p) : -edge(b, a, p);
  if (e != 0.0) return e > 0.0;
  return b.y > a.y || (b.y == a.y && b.x < a.x);
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  uint index = uint(pixel.y * u_size + pixel.x);
  // Counter-clockwise order (GL's window y points up).
  vec2 b = v_b, c = v_c;
  if (edge(v_a, v_b, v_c) < 0.0) {
    b = v_c;
    c = v_b;
  }
  uint mask = 0u;
  for (int k = 0; k < max(u_samples, 1); ++k) {
    vec2 p = vec2(pixel) + coverageSampleOffset(u_seed, v_point, index, k, u_samples);
    if (inside(v_a, b, p) && inside(b, c, p) && inside(c, v_a, p)) mask |= 1u << uint(k);
  }
  if (mask == 0u) discard;
  o_mask = mask;
  gl_FragDepth = clamp(v_depth_plane.z + dot(v_depth_plane.xy, gl_FragCoord.xy - v_a), 0.0, 1.0);
}
