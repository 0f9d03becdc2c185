// The BVH's traversal (GpuBvh; bvh_shared.h has the layout): Aila & Laine's "while-while" loop
// (HPG 2009) with a per-ray stack. castBvh (bvh.cpp) is the same algorithm on the CPU, step for
// step, and the tests compare the two.
#include "realtime/ray_casting/bvh_shared.h"
#include "realtime/ray_casting/ray_triangles.glsl"

layout(binding = kRayNodesUnit) uniform samplerBuffer u_bvh_nodes;

RayCastHit castRayBvh(vec3 o, vec3 d, float t_min, float t_max) {
  RayCastHit hit = rayCastStart(t_max);
  vec3 inv_d = bvhInverseDirection(d);
  // The builder bounds the inner nodes on any path by kBvhStackSize, and a path pushes at most
  // one reference per inner node, so the stack never overflows.
  uint stack[kBvhStackSize];
  int depth = 0;
  uint reference = kBvhRootReference;
  for (;;) {
    // Inner nodes: both children's boxes from one node; into the nearer one hit, the farther
    // one hit kept on the stack.
    while (!bvhIsLeaf(reference)) {
      int base = int(reference) * kBvhNodeTexels;
      vec4 min0 = texelFetch(u_bvh_nodes, base);
      vec4 max0 = texelFetch(u_bvh_nodes, base + 1);
      vec4 min1 = texelFetch(u_bvh_nodes, base + 2);
      vec4 max1 = texelFetch(u_bvh_nodes, base + 3);
      vec2 span0 = bvhBoxSpan(min0.xyz, max0.xyz, o, inv_d, t_min, hit.t);
      vec2 span1 = bvhBoxSpan(min1.xyz, max1.xyz, o, inv_d, t_min, hit.t);
      bool enter0 = span0.x <= span0.y, enter1 = span1.x <= span1.y;
      uint child0 = floatBitsToUint(min0.w), child1 = floatBitsToUint(min1.w);
      if (enter0 && enter1) {
        bool second_nearer = span1.x < span0.x;
        stack[depth++] = second_nearer ? child0 : child1;
        reference = second_nearer ? child1 : child0;
      } else if (enter0) {
        reference = child0;
      } else if (enter1) {
        reference = child1;
      } else {
        if (depth == 0) return castRayFinish(hit);
        reference = stack[--depth];
      }
    }
    // A leaf: its triangles, consecutive slots.
    int first = int(bvhLeafFirst(reference));
    int end = first + int(bvhLeafCount(reference));
    for (int slot = first; slot < end; ++slot) castRayTriangle(slot, o, d, t_min, hit);
    if (depth == 0) break;
    reference = stack[--depth];
  }
  return castRayFinish(hit);
}
