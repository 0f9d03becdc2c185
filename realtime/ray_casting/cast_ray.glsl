// castRay(o, d, t_min, t_max): the closest hit through the structure the program was built for
// (GpuRayStructure::castDefines: GIB_CAST_RAY names its function, GIB_RAY_STRUCTURE_<NAME> keeps
// its file; the others' text stays out, so their samplers at the shared units do not clash).
#include "realtime/ray_casting/ray_triangles.glsl"
#include "realtime/ray_casting/brute_force.glsl"
#ifdef GIB_RAY_STRUCTURE_LOOSE_KD_TREE
#include "realtime/ray_casting/loose_kd_tree.glsl"
#endif
#ifdef GIB_RAY_STRUCTURE_BVH
#include "realtime/ray_casting/bvh.glsl"
#endif

RayCastHit castRay(vec3 o, vec3 d, float t_min, float t_max) {
  return GIB_CAST_RAY(o, d, t_min, t_max);
}
