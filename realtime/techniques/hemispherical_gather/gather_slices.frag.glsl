// A fish-eye view's pixel seen through the voxel slices: the direction whose tangent-plane
// coordinates are the pixel's (§5.4, eq. 7: S = E + Fx·r + Fy·u + λ·v, λ = √(1 − Fx² − Fy²)),
// traced through the slices beyond the near box; its depth is the distance, in the near
// geometry's own depth metric, so the nearer of the two wins the depth test.
#include "realtime/techniques/hemispherical_gather/gather_point.glsl"
#include "realtime/techniques/hemispherical_gather/voxel_slices.glsl"

uniform int u_first_point;
uniform int u_size;
uniform float u_near;
uniform float u_far;
uniform vec3 u_near_box;
layout(location = 0) out vec4 o_radiance;

void main() {
  GatherFrame f;
  if (!gatherFrame(u_first_point + gl_Layer, f)) discard;
  vec2 xy = gl_FragCoord.xy / float(u_size) * 2.0 - 1.0;
  float lambda2 = 1.0 - dot(xy, xy);
  if (lambda2 <= 0.0) discard;  // outside the hemisphere's disk
  vec3 direction = xy.x * f.t + xy.y * f.b + sqrt(lambda2) * f.n;
  float distance;
  vec3 radiance;
  if (!traceSlices(f.origin, direction, u_near_box, distance, radiance)) discard;
  o_radiance = vec4(radiance, 1.0);
  gl_FragDepth = clamp((distance - u_near) / (u_far - u_near), 0.0, 1.0);
}
