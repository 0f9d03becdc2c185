// The ray engine's intersection (§5.2): the pixel's ray against the fragment's triangle; a hit
// writes (t, list index + 1, u, v) and its depth t/(t + s), which the depth test (GL_LESS) keeps
// only when nearer than what the pixel holds. y = 0 (the clear) means no hit.
#include "realtime/ray_casting/ray_triangles.glsl"
#include "realtime/ray_casting/ray_engine_shared.h"

layout(binding = kRayEngineOriginsUnit) uniform sampler2D u_origins;
layout(binding = kRayEngineDirectionsUnit) uniform sampler2D u_directions;
uniform int u_ray_count;
uniform int u_width;
uniform float u_depth_scale;
flat in int v_slot;
layout(location = 0) out vec4 o_hit;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  if (pixel.x >= u_width || pixel.y * u_width + pixel.x >= u_ray_count) discard;
  vec4 origin = texelFetch(u_origins, pixel, 0);
  vec4 direction = texelFetch(u_directions, pixel, 0);
  RayCastHit hit = rayCastStart(direction.w);
  castRayTriangle(v_slot, origin.xyz, direction.xyz, origin.w, hit);
  if (hit.triangle == kNoRayTriangle) discard;
  hit = castRayFinish(hit);
  gl_FragDepth = hit.t / (hit.t + u_depth_scale);
  o_hit = vec4(hit.t, float(hit.triangle) + 1.0, hit.u, hit.v);
}
