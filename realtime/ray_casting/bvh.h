// A binary bounding volume hierarchy for the ray-casting table
// (realtime/ray_casting/README.md, "The BVH"): what a modern GPU ray caster traverses, beside the
// book's structures of Ch. 5 (the ray engine, the loose kd-tree; §5.4.3 cites a stackless, threaded
// BVH). Built on the CPU with the binned surface-area heuristic (Wald, "On fast construction of
// SAH-based bounding volume hierarchies", IEEE Symposium on Interactive Ray Tracing 2007), laid out
// and traversed as Aila & Laine, "Understanding the efficiency of ray traversal on GPUs" (HPG 2009)
// describe: both children's boxes in the parent, a "while-while" loop with a per-ray stack
// (bvh_shared.h, bvh.glsl). Its leaves test triangles with the book's IVM test (§5.1), as every
// structure of the table does, so the table compares structures, not triangle tests.
#pragma once

#include "realtime/gl/objects.h"
#include "realtime/ray_casting/bvh_shared.h"
#include "realtime/ray_casting/gpu_ray_structure.h"
#include "realtime/ray_casting/ivm_triangles.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace gib::rt {

struct BvhSettings {
  // A node of at most this many triangles may become a leaf (when the SAH finds no cheaper
  // split); a larger one is always split. 1 to gpu::kBvhMaxLeafSize. 4 is Aila & Laine's leaf
  // size for their SAH trees and the usual choice of GPU BVHs since.
  int max_leaf_size = 4;
  // The SAH's cost of visiting an inner node (one 64-byte fetch, two slab tests) and of one IVM
  // test (three texels, three dot products and a division), in the same unit. Equal costs: on a
  // GPU both are dominated by their memory fetches, which are of similar size.
  float traversal_cost = 1.0f;
  float triangle_cost = 1.0f;
  // Bins per axis over the node's centroid bounds (Wald 2007 uses 16 to 32 and finds 16 within a
  // few percent of a full sweep); every axis is binned, the cheapest plane of the three taken.
  // 2 to 256.
  int bins = 32;
  // The most inner nodes on a path from the root (the traversal's stack needs as many entries):
  // where the SAH split would exceed it, the node is split at its median instead. 1 to
  // gpu::kBvhStackSize; a smaller bound is for tests of the fallback.
  int max_depth = gpu::kBvhStackSize;
};

struct Bvh {
  // gpu::kBvhNodeTexels texels per inner node (bvh_shared.h), the root first: what the GPU reads.
  std::vector<glm::vec4> nodes;
  // triangle_order[slot] is the IvmTriangleSet index of the triangle at that slot; a leaf's
  // triangles are a run of consecutive slots (its reference's first slot and count).
  std::vector<std::uint32_t> triangle_order;

  // Statistics for the table.
  std::size_t inner_nodes = 0;
  std::size_t leaves = 0;  // non-empty leaves
  int max_depth = 0;       // inner nodes on the longest path from the root to a leaf
  int max_leaf_size = 0;   // triangles in the largest leaf
  // The tree's cost under the surface-area model: traversal_cost per inner node and
  // triangle_cost per triangle, each weighed by its box's area over the root's (the expected cost
  // of a ray that crosses the scene's bounds, by the SAH's assumptions).
  double sah_cost = 0.0;

  std::size_t nodeCount() const { return nodes.size() / gpu::kBvhNodeTexels; }
  // The bytes of the node array (the GPU's node buffer; the triangles are counted apart).
  std::size_t bytes() const { return nodes.size() * sizeof(glm::vec4); }
};

// Builds the hierarchy over every triangle of the set. Deterministic: the same set and settings
// give the same bits (stable partitions, ties broken by axis and bin order). Throws
// gib::InputError for settings outside their ranges, a max_depth too small for the scene's
// triangles at max_leaf_size each, or more than gpu::kBvhMaxTriangles triangles.
Bvh buildBvh(const IvmTriangleSet& set, const BvhSettings& settings = {});

// The closest hit of a ray (in the set's coordinates) through the packed node array, by the
// algorithm and the arithmetic of bvh.glsl: what the tests hold the GPU to. A miss has
// t = gpu::kRayInfinity and triangle gpu::kNoRayTriangle.
gpu::RayCastHit castBvh(const Bvh& bvh, const IvmTriangleSet& set, const glm::vec3& o,
                        const glm::vec3& d, float t_min, float t_max);

// The hierarchy on the GPU (castRayBvh in bvh.glsl): the nodes as an RGBA32F buffer texture at
// kRayNodesUnit, the triangles in the hierarchy's slot order at kRayTrianglesUnit.
class GpuBvh final : public GpuRayStructure {
 public:
  explicit GpuBvh(const IvmTriangleSet& set, const BvhSettings& settings = {});
  std::string_view name() const override { return "bvh"; }
  std::string_view castFunction() const override { return "castRayBvh"; }
  void bind() const override;
  std::size_t bytes() const override { return triangles_.bytes() + nodes_buffer_.bytes(); }
  // The CPU hierarchy it uploaded (its statistics for the table; castBvh for checks).
  const Bvh& bvh() const { return bvh_; }

 private:
  Bvh bvh_;
  GpuRayTriangles triangles_;
  gl::Buffer nodes_buffer_;
  gl::Texture nodes_texture_;
};

}  // namespace gib::rt
