// The BVH of the ray-casting table (realtime/ray_casting/README.md, "The BVH"), written once for
// its CPU builder, its CPU traversal (which the tests hold the GPU to) and its shader: the node
// record, the child references, the stack bound and the ray-box slab test.
//
// The layout is Aila & Laine's ("Understanding the efficiency of ray traversal on GPUs", HPG
// 2009): an inner node holds the boxes of BOTH its children and their references, so one fetch
// of a node tests both children and the traversal never fetches a node whose box the ray misses.
#pragma once
#include "realtime/gl/host_device_shared.h"
#include "realtime/ray_casting/ray_casting_shared.h"

#ifdef __cplusplus
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

namespace gib::rt::gpu {
using glm::abs;
using glm::bvec3;
using glm::lessThan;
using glm::max;
using glm::min;
using glm::mix;
#endif

// An inner node is kBvhNodeTexels RGBA32F texels of the buffer texture at kRayNodesUnit, node n
// at texels kBvhNodeTexels·n onwards (64 bytes):
//   0: child 0's box minimum (xyz), child 0's reference (w, uint bits)
//   1: child 0's box maximum (xyz), 0
//   2: child 1's box minimum (xyz), child 1's reference (w, uint bits)
//   3: child 1's box maximum (xyz), 0
// Boxes are in the triangle set's coordinates (IvmTriangleSet::origin at 0), rounded outward.
// The root is inner node 0, always (a scene that fits one leaf gets a root whose child 1 is
// kBvhEmptyReference under an inverted box, which no ray enters).
const int kBvhNodeTexels = 4;

// A child reference: bit 31 clear, an inner node's index; bit 31 set, a leaf: its triangle count
// in bits 26–30 (1 to kBvhMaxLeafSize) and its first triangle slot in bits 0–25 (the slots of
// the triangle buffer texture, ray_triangles.glsl; a leaf's triangles are consecutive slots).
const uint kBvhLeafBit = 0x80000000u;
const uint kBvhLeafCountShift = 26u;
const uint kBvhLeafFirstMask = 0x03ffffffu;
const int kBvhMaxLeafSize = 31;
// 2²⁶ slots: more than the 44 M triangles a 2²⁷-texel buffer texture (the largest GL drivers
// offer) holds at three texels each.
const int kBvhMaxTriangles = 67108864;
// An empty child: a leaf of no triangles.
const uint kBvhEmptyReference = 0x80000000u;
const uint kBvhRootReference = 0u;

// The traversal's stack holds at most one reference per inner node on the path from the root,
// so the builder bounds that depth by this (falling back to median splits) and the stack never
// overflows. 64 entries are Aila & Laine's; the chamber at detail 5 needs 19.
const int kBvhStackSize = 64;

// A direction component smaller than this in magnitude is replaced by it (sign kept) before the
// reciprocal, so 1/d is finite and (box − o)·(1/d) is never 0·∞ = NaN when the ray's origin lies
// on a box face. Aila & Laine's kernels do the same with 2⁻⁸⁰: along that component the ray then
// moves 2⁻⁸⁰ per unit of t, a box reached only at t ~ 10²⁴ further away than any scene extent.
const float kBvhTinyDirection = 8.2718061255302767e-25f;  // 2⁻⁸⁰

// The slab test's far end is scaled by this before the comparison, so that the rounding of
// (box − o)·(1/d) (three roundings, and GLSL's reciprocal may be 2.5 ulp off) never makes a ray
// that touches a box miss it: Ize's "Robust BVH ray traversal" (JCGT 2013) scales by 1 + 2γ₃
// (≈ 1 + 3.6·10⁻⁷) for IEEE arithmetic; 1 + 2⁻²⁰ leaves room for the shader's looser division.
const float kBvhExitScale = 1.00000095367431640625f;  // 1 + 2⁻²⁰

GIB_SHARED_FUNCTION bool bvhIsLeaf(uint reference) {
  return (reference & kBvhLeafBit) != 0u;
}
GIB_SHARED_FUNCTION uint bvhLeafFirst(uint reference) {
  return reference & kBvhLeafFirstMask;
}
GIB_SHARED_FUNCTION uint bvhLeafCount(uint reference) {
  return (reference & ~kBvhLeafBit) >> kBvhLeafCountShift;
}
GIB_SHARED_FUNCTION uint bvhLeafReference(uint first, uint count) {
  return kBvhLeafBit | (count << kBvhLeafCountShift) | first;
}

// The reciprocal direction the slab test multiplies by (kBvhTinyDirection).
GIB_SHARED_FUNCTION vec3 bvhInverseDirection(vec3 d) {
  vec3 tiny = mix(vec3(kBvhTinyDirection), vec3(-kBvhTinyDirection), lessThan(d, vec3(0.0f)));
  vec3 safe = mix(tiny, d, lessThan(vec3(kBvhTinyDirection), abs(d)));
  return vec3(1.0f) / safe;
}

// The slab test of the ray o + t·d (inv_d = bvhInverseDirection(d)) against the box
// [box_min, box_max]: returns (t_entry, t_exit) clipped to [t_min, t_max]; the ray enters the box
// when t_entry ≤ t_exit (inclusive, so a ray along a face, or one that touches a corner, counts).
// Each axis's near plane is chosen by the sign of inv_d, not by min/max of the two distances, so
// an inverted box (min > max: kBvhEmptyReference's) is never entered.
GIB_SHARED_FUNCTION vec2 bvhBoxSpan(vec3 box_min, vec3 box_max, vec3 o, vec3 inv_d, float t_min,
                                    float t_max) {
  bvec3 negative = lessThan(inv_d, vec3(0.0f));
  vec3 near_plane = mix(box_min, box_max, negative);
  vec3 far_plane = mix(box_max, box_min, negative);
  vec3 t_near = (near_plane - o) * inv_d;
  vec3 t_far = (far_plane - o) * inv_d;
  float t_entry = max(max(t_near.x, t_near.y), max(t_near.z, t_min));
  float t_exit = min(min(t_far.x, t_far.y), t_far.z) * kBvhExitScale;
  return vec2(t_entry, min(t_exit, t_max));
}

#ifdef __cplusplus
static_assert(kBvhMaxLeafSize == int((kBvhLeafBit >> kBvhLeafCountShift) - 1u));
static_assert(unsigned(kBvhMaxTriangles) == kBvhLeafFirstMask + 1u);
}  // namespace gib::rt::gpu
#endif
