// The loose kd-tree's traversal (book §5.5.2; GpuLooseKdTree): node words at kRayNodesUnit, their
// flags at kRayFlagsUnit (loose_kd_tree_shared.h), the triangles in leaf order at
// kRayTrianglesUnit. castLooseKdTree (loose_kd_tree.cpp) is this function on the CPU, step for
// step, and the tests hold the two to each other.
//
// The ray's segment starts as (t_min, t_max), as the book's does, not clipped to the scene's
// box: the root cell is unbounded (a cut stores one plane per child), and the rays cast here
// start inside the scene, where clipping would cut nothing off; it would cost the root box's six
// planes in the node buffer and a slab test per ray.
//
// What differs from the book's listing, besides HLSL turned into GLSL:
//   - it declares `float4 stack[36]` and pushes to `traversalStack`, computes `invd` and reads
//     `invRayDir`, takes `o` and reads `rayOrigin`: one name each here;
//   - the inner loop redeclares `uint nodeFlags`, shadowing the outer variable its condition
//     tests, so the loop never sees the child's flags: here one `flag`, fetched per node;
//   - a node index stored as float bits (`asfloat(node)`) is a denormal that a GPU may flush to
//     zero on a move: the stack keeps node slots in a uint array;
//   - the far segment is pushed only when strictly positive, the near one taken when it is a
//     point: a ray crossing a flat cell (a wall's triangles alone, both planes equal) would skip
//     it as the far child. Both are kept here when start ≤ end;
//   - when neither child's segment is non-empty the listing still descends into the far child
//     and tests the triangles of whatever leaf it reaches; here the next entry is popped;
//   - (plane − o)·(1/d) is NaN for a ray parallel to the planes that lies on one:
//     looseKdChildSegments decides such a ray by its origin;
//   - processTriangle records as the hit the texel index after its three increments (the next
//     triangle's); castRayTriangle names the triangle by the index its first texel carries;
//   - leaves address slots of a buffer texture, so a leaf's run never wraps around a texture row
//     as the listing's 2048-texel rows would.
#include "realtime/ray_casting/loose_kd_tree_shared.h"
#include "realtime/ray_casting/ray_triangles.glsl"

layout(binding = kRayNodesUnit) uniform usamplerBuffer u_loose_kd_nodes;
layout(binding = kRayFlagsUnit) uniform usamplerBuffer u_loose_kd_flags;

RayCastHit castRayLooseKdTree(vec3 o, vec3 d, float t_min, float t_max) {
  // 1/d is read only along axes where d ≠ 0 (looseKdChildSegments), so its infinities are moot.
  vec3 inv_d = 1.0 / d;
  RayCastHit hit = rayCastStart(t_max);
  uint stack_node[kLooseKdMaxDepth];
  vec2 stack_segment[kLooseKdMaxDepth];
  int top = 0;
  uint node = 0u;  // the root: block 0, node 0
  vec2 segment = vec2(t_min, t_max);
  for (;;) {
    if (segment.x <= segment.y) {
      uint flag = texelFetch(u_loose_kd_flags, int(node)).r;
      if (flag != kLooseKdLeafFlag) {
        // A cut: follow a pointer slot to its block's node 0 (the book's getChild), then split
        // the segment between the near and the far child.
        if (looseKdIsLastLevel(node))
          node = looseKdBlockRoot(texelFetch(u_loose_kd_nodes, int(node)).r);
        vec2 planes = looseKdCutPlanes(texelFetch(u_loose_kd_nodes, int(node)).r);
        int a = int(flag);
        vec4 s = looseKdChildSegments(planes, o[a], d[a], inv_d[a], segment);
        uint left = looseKdLeftChild(node);
        bool near_is_left = looseKdNearIsLeft(d[a]);
        uint near_child = near_is_left ? left : left + 1u;
        uint far_child = near_is_left ? left + 1u : left;
        if (s.x <= s.y) {
          if (s.z <= s.w) {
            // The builder bounds the depth so that this never overflows (kLooseKdMaxDepth).
            stack_node[top] = far_child;
            stack_segment[top] = s.zw;
            ++top;
          }
          node = near_child;
          segment = s.xy;
        } else {
          node = far_child;
          segment = s.zw;
        }
        continue;
      }
      // A leaf: its triangles over the whole ray (each lies wholly in this cell).
      uint word = texelFetch(u_loose_kd_nodes, int(node)).r;
      int start = int(looseKdLeafStart(word));
      int end = start + int(looseKdLeafCount(word));
      for (int slot = start; slot < end; ++slot) castRayTriangle(slot, o, d, t_min, hit);
    }
    // The next far child, its segment cut at the best hit so far.
    if (top == 0) break;
    --top;
    node = stack_node[top];
    segment = vec2(stack_segment[top].x, min(stack_segment[top].y, hit.t));
  }
  return castRayFinish(hit);
}
