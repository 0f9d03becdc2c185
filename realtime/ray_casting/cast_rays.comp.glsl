// Casts a batch of rays through a structure (RayCastPass): ray i is records 2i (origin, t_min)
// and 2i + 1 (direction, t_max) of the rays buffer, in the set's coordinates; its closest hit
// goes to hits[i].
#include "realtime/ray_casting/cast_ray.glsl"
#include "realtime/ray_casting/ray_cast_pass_shared.h"

layout(local_size_x = kCastGroupSize) in;
layout(std430, binding = kCastRaysBinding) readonly buffer Rays { vec4 u_rays[]; };
layout(std430, binding = kCastHitsBinding) writeonly buffer Hits { RayCastHit u_hits[]; };
uniform uint u_ray_count;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_ray_count) return;
  vec4 origin = u_rays[2 * i], direction = u_rays[2 * i + 1];
  u_hits[i] = castRay(origin.xyz, direction.xyz, origin.w, direction.w);
}
