// The loose kd-tree of book §5.5 (realtime/ray_casting/README.md, "The loose kd-tree"), written
// once for its CPU builder, its CPU traversal (which the tests hold the GPU to) and its shader: the
// node word, the flags, the blocks of the compact layout, the stack bound and the step through a
// cut.
//
// A loose kd-tree cuts a cell into two cells that may overlap or leave a gap (Fig. 5.11): every
// triangle goes wholly into one child, and each child stores the one plane the cut moved, the
// left child's maximum and the right child's minimum along the cut axis. Its cell is its parent's
// with that plane replaced, so the cells nest and a triangle lies inside its leaf's cell and in
// every ancestor's.
#pragma once
#include "realtime/gl/host_device_shared.h"
#include "realtime/ray_casting/ray_casting_shared.h"

#ifdef __cplusplus
#include <glm/common.hpp>
#include <glm/packing.hpp>

namespace gib::rt::gpu {
using glm::max;
using glm::min;
using glm::packHalf2x16;
using glm::unpackHalf2x16;
#endif

// ---- Flags: one R8UI texel per node slot at kRayFlagsUnit (the book's 2-bit flag texture) ----
// 0, 1, 2: a cut along x, y, z (a cut node, or a pointer slot whose target is one); 3: a leaf.
// A slot is a pointer when it is not a leaf and lies on its block's last level (the book's rule:
// "not a leaf node, but on the last level of a node block").
const uint kLooseKdLeafFlag = 3u;

// ---- Blocks (Fig. 5.13): node slot s of the R32UI buffer texture at kRayNodesUnit ----
// A block is a complete binary tree of kLooseKdBlockLevels levels laid out level by level, the
// children of in-block node n at 2n + 1 and 2n + 2; a cut node on the last level, whose children
// would fall outside, is a pointer slot: its word is the index of the block whose node 0 holds
// the cut, and the cut's children are that block's nodes 1 and 2 (the book's getChild). Node 0 of
// a block is never a pointer, so one redirection always reaches the cut. Blocks are
// kLooseKdBlockStride slots apart, one slot more than the 2^L − 1 nodes of a block, so that the
// block and in-block index are a shift and a mask rather than an integer division (the padding
// slot is an empty leaf no child index reaches). The root is node 0 of block 0.
//
// Four levels (15 nodes, 16 slots): on the chamber at detail 5 (README.md) three
// levels take 600 KiB of words and flags, four 835, five 1 030, eight 7 300, since a block opened
// under an unbalanced subtree leaves most of its slots empty; fewer levels redirect more often
// (a dependent fetch per block crossed: every second cut at three levels, every third at four).
// The CPU traversal times them alike; the triangles' 4 MiB dwarf either layout.
const int kLooseKdBlockLevels = 4;
const int kLooseKdBlockStride = 1 << kLooseKdBlockLevels;
const int kLooseKdNodesPerBlock = kLooseKdBlockStride - 1;
// In-block indices from here on are the last level: pointer slots when not leaves.
const int kLooseKdFirstLastLevelNode = (1 << (kLooseKdBlockLevels - 1)) - 1;

// ---- Node words (32 bits) ----
// Cut node: the two planes as halves (packHalf2x16), the left child's maximum in the low 16 bits
// and the right child's minimum in the high 16, in the set's coordinates (IvmTriangleSet::origin
// at 0). Halves carry 11 significant bits, so the builder rounds outward (the maximum up, the
// minimum down, to the next representable half): a cell grows by up to 2⁻¹¹ of its planes'
// magnitude but never cuts a triangle, which the book's 16-bit floats do not say how to ensure.
// An empty child's plane is −∞ (left) or +∞ (right): no ray's segment reaches it.
// Leaf: the triangle count in the high kLooseKdLeafCountBits bits, the first triangle slot (of the
// buffer texture at kRayTrianglesUnit, whose leaves are consecutive runs) in the low
// kLooseKdLeafStartBits. The book's two 16-bit integers address 65 536 slots, fewer than the
// chamber's 85 000 triangles; 24 bits address 16 M, and a leaf of more than 255 triangles is
// never wanted (the builder splits at the median any cell that large that SAH would keep).
// Pointer: the index of the target block.
const uint kLooseKdLeafStartBits = 24u;
const uint kLooseKdLeafStartMask = 0x00ffffffu;
const int kLooseKdMaxLeafTriangles = 255;
const int kLooseKdMaxTriangles = 16777216;  // 2^24 slots

// ---- Stack ----
// A leaf lies at most this many cuts below the root (the builder guarantees it, falling back to
// median splits near the bound). The traversal pushes at most one far child per level and pops
// before it descends from a popped node, so its stack holds entries of strictly increasing depth
// from 1 to the leaf's: this many entries never overflow. The book's listing uses 36; the chamber
// at detail 5 reaches 22 with the default settings.
const int kLooseKdMaxDepth = 40;

GIB_SHARED_FUNCTION uint looseKdLeafWord(uint start, uint count) {
  return (count << kLooseKdLeafStartBits) | start;
}
GIB_SHARED_FUNCTION uint looseKdLeafStart(uint word) {
  return word & kLooseKdLeafStartMask;
}
GIB_SHARED_FUNCTION uint looseKdLeafCount(uint word) {
  return word >> kLooseKdLeafStartBits;
}

// (left child's maximum, right child's minimum) of a cut node's word.
GIB_SHARED_FUNCTION vec2 looseKdCutPlanes(uint word) {
  return unpackHalf2x16(word);
}

GIB_SHARED_FUNCTION uint looseKdBlockRoot(uint block) {
  return block << uint(kLooseKdBlockLevels);
}
GIB_SHARED_FUNCTION bool looseKdIsLastLevel(uint slot) {
  return int(slot & uint(kLooseKdBlockStride - 1)) >= kLooseKdFirstLastLevelNode;
}
// The slot of a cut node's left child (the right child is the next slot); `slot` holds the cut
// itself, not a pointer to it.
GIB_SHARED_FUNCTION uint looseKdLeftChild(uint slot) {
  uint in_block = slot & uint(kLooseKdBlockStride - 1);
  return slot - in_block + 2u * in_block + 1u;
}

// Whether the left child is the near one for a ray whose direction along the cut axis is d_a. A
// ray parallel to the planes (d_a = ±0) takes the left first; either order is right for it,
// since its segments do not depend on it.
GIB_SHARED_FUNCTION bool looseKdNearIsLeft(float d_a) {
  return !(d_a < 0.0f);
}

// Where the ray crosses the plane at `plane` along the axis, for d_a ≠ 0. (plane − o)·(1/d) is
// 0·∞ = NaN when the ray starts on the plane and 1/d overflowed (d a denormal); the crossing is
// then at t = 0.
GIB_SHARED_FUNCTION float looseKdPlaneT(float plane, float o_a, float inv_d_a) {
  float diff = plane - o_a;
  return diff == 0.0f ? 0.0f : diff * inv_d_a;
}

// The segments of the near and far child (near.xy, far.zw) of a cut with planes `planes`
// (looseKdCutPlanes) for the ray's segment `segment` = (t_start, t_end), along the cut axis a.
// A segment is empty when its start exceeds its end; an empty-but-one-point segment is kept, so
// a ray crossing a flat cell (a wall's triangles alone, its two planes equal) still visits it.
// The near child's segment ends where the ray leaves it (the book's nearSegment), the far child's
// begins where it enters (farSegment); they overlap when the cells do. A ray parallel to the
// planes (d_a == 0, where 1/d would give (plane − o)·∞ = NaN on the plane itself) is inside a
// child for all t or for none, by where its origin lies; the planes belong to their cells.
GIB_SHARED_FUNCTION vec4 looseKdChildSegments(vec2 planes, float o_a, float d_a, float inv_d_a,
                                              vec2 segment) {
  float near_exit;
  float far_entry;
  if (d_a == 0.0f) {
    near_exit = o_a <= planes.x ? kRayInfinity : -kRayInfinity;
    far_entry = o_a >= planes.y ? -kRayInfinity : kRayInfinity;
  } else if (d_a > 0.0f) {
    near_exit = looseKdPlaneT(planes.x, o_a, inv_d_a);  // leaves the left cell at its maximum
    far_entry = looseKdPlaneT(planes.y, o_a, inv_d_a);  // enters the right cell at its minimum
  } else {
    near_exit = looseKdPlaneT(planes.y, o_a, inv_d_a);  // leaves the right cell at its minimum
    far_entry = looseKdPlaneT(planes.x, o_a, inv_d_a);  // enters the left cell at its maximum
  }
  return vec4(segment.x, min(segment.y, near_exit), max(segment.x, far_entry), segment.y);
}

#ifdef __cplusplus
static_assert(kLooseKdMaxLeafTriangles < (1 << (32 - int(kLooseKdLeafStartBits))));
static_assert(kLooseKdMaxTriangles == int(kLooseKdLeafStartMask) + 1);
static_assert(kLooseKdBlockLevels >= 2, "node 0 of a block must not be on its last level");
}  // namespace gib::rt::gpu
#endif
