// The triangles of a ray-casting structure (ray_casting_shared.h): the IVM rows and apex of the
// triangle in slot s at texels 3s .. 3s + 2 of the buffer texture at kRayTrianglesUnit, and after
// all N triangles the slots' list indices, four to a texel.
#include "realtime/ray_casting/ray_casting_shared.h"

layout(binding = kRayTrianglesUnit) uniform samplerBuffer u_ray_triangles;

// The slots the buffer texture holds: 3N texels of triangles and ⌈N/4⌉ of indices.
int rayTriangleCount() {
  int texels = textureSize(u_ray_triangles);
  // 3N + ⌈N/4⌉ = texels: N = ⌊4·texels/13⌋ is exact for every N (13N/4 ≤ texels < 13N/4 + 1).
  return (4 * texels) / 13;
}

// The §5.1 test of the triangle in `slot` against the ray, updating `hit` (its triangle field
// the slot, until castRayFinish names it) when nearer.
void castRayTriangle(int slot, vec3 o, vec3 d, float t_min, inout RayCastHit hit) {
  int base = slot * kRayTriangleTexels;
  vec4 r0 = texelFetch(u_ray_triangles, base);
  vec4 r1 = texelFetch(u_ray_triangles, base + 1);
  vec4 r2 = texelFetch(u_ray_triangles, base + 2);
  vec3 apex = vec3(r0.w, r1.w, r2.w);
  vec4 r = intersectIvm(o - apex, d, r0.xyz, r1.xyz, r2.xyz, t_min, hit.t);
  if (r.x < hit.t) hit = RayCastHit(r.x, uint(slot), r.z, r.w);
}

// A miss, its t the ray's far end while casting.
RayCastHit rayCastStart(float t_max) { return RayCastHit(t_max, kNoRayTriangle, 0.0, 0.0); }

// The hit as a cast returns it: the slot's list index, or a miss at kRayInfinity.
RayCastHit castRayFinish(RayCastHit hit) {
  if (hit.triangle == kNoRayTriangle) {
    hit.t = kRayInfinity;
    return hit;
  }
  int slot = int(hit.triangle);
  vec4 indices = texelFetch(u_ray_triangles, kRayTriangleTexels * rayTriangleCount() + slot / 4);
  hit.triangle = floatBitsToUint(indices[slot % 4]);
  return hit;
}
