// §5.1 alone: the ray against every triangle, in list order (GpuBruteForce).
#include "realtime/ray_casting/ray_triangles.glsl"

RayCastHit castRayBruteForce(vec3 o, vec3 d, float t_min, float t_max) {
  RayCastHit hit = rayCastStart(t_max);
  int count = rayTriangleCount();
  for (int slot = 0; slot < count; ++slot) castRayTriangle(slot, o, d, t_min, hit);
  return castRayFinish(hit);
}
