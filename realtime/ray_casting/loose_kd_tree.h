// The loose kd-tree of book §5.5 (Woop et al.'s bounding kd-tree): built on the CPU with the
// surface area heuristic of §5.4.4 adapted to loose cells (Fig. 5.12), packed into the compact
// blocks of Fig. 5.13 (loose_kd_tree_shared.h), traversed on the GPU (loose_kd_tree.glsl) and,
// for the tests, by the same algorithm on the CPU over the same packed words.
// realtime/ray_casting/README.md, "The loose kd-tree" describes the layout and the choices.
#pragma once

#include "realtime/gl/objects.h"
#include "realtime/ray_casting/gpu_ray_structure.h"
#include "realtime/ray_casting/ivm_triangles.h"
#include "realtime/ray_casting/loose_kd_tree_shared.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace gib::rt {

struct LooseKdTreeSettings {
  // A cell of at most this many triangles becomes a leaf without a cut being tried (1 to
  // gpu::kLooseKdMaxLeafTriangles). On the chamber at detail 5 the CPU traversal cast as fast
  // with 4 as with 2 (which needs 1.7 times the node words) and faster than with 8 or 16
  // (README.md).
  int max_leaf_triangles = 4;
  // SAH costs (§5.4.4): a cut costs traversal_cost + (A_L·N_L + A_R·N_R)/A · intersection_cost,
  // a leaf N · intersection_cost. Only their ratio matters; the IVM test fetches three texels
  // against a node's two (word and flags) and computes more, hence 1.5.
  float traversal_cost = 1.0f;
  float intersection_cost = 1.5f;
  // Levels of a block of the compact layout. The shader is compiled for
  // gpu::kLooseKdBlockLevels, so GpuLooseKdTree takes only that; other values are for measuring
  // the CPU traversal and the layout's size (2 to 16).
  int block_levels = gpu::kLooseKdBlockLevels;
  // The deepest a leaf may lie (1 to gpu::kLooseKdMaxDepth, the shader's stack): the builder
  // splits at the median, where SAH would go deeper, to keep within it.
  int max_depth = gpu::kLooseKdMaxDepth;
};

struct LooseKdTree {
  // Node slots of the packed layout: words (loose_kd_tree_shared.h) and their flags, one each.
  std::vector<std::uint32_t> nodes;
  std::vector<std::uint8_t> flags;
  // triangle_order[slot]: the IvmTriangleSet index of the triangle in that slot; a leaf's
  // triangles are consecutive slots.
  std::vector<std::uint32_t> triangle_order;
  int block_levels = gpu::kLooseKdBlockLevels;

  // What the build made (the bench's table).
  std::size_t blocks = 0;
  std::size_t cut_nodes = 0;      // cuts, each counted once (not their pointer slots)
  std::size_t pointer_slots = 0;  // last-level slots redirecting to another block
  std::size_t leaves = 0;         // leaves with triangles
  std::size_t empty_leaves = 0;   // the empty side of a cut that trimmed empty space
  std::size_t median_splits = 0;  // cuts forced at the median (> 255 triangles, or the depth bound)
  int max_depth = 0;              // cuts above the deepest leaf
  int max_leaf_triangles = 0;     // the largest leaf
  double mean_leaf_triangles = 0.0;  // over leaves with triangles
  // The SAH's estimate of a random ray's cost through the tree, relative to a cell of the root's
  // size (Σ over cuts of A/A_root · C_trav + Σ over leaves of A/A_root · N · C_isect): what the
  // settings minimise, for comparing builds.
  double sah_cost = 0.0;

  // Bytes of the node words and flags (the structure beyond the triangles themselves).
  std::size_t bytes() const { return nodes.size() * sizeof(std::uint32_t) + flags.size(); }
};

// Builds the tree over every triangle of the set (deterministic: the same set and settings give
// the same words). Throws std::invalid_argument for settings out of range, and gib::InputError
// when the set has more than gpu::kLooseKdMaxTriangles triangles.
LooseKdTree buildLooseKdTree(const IvmTriangleSet& set, const LooseKdTreeSettings& settings = {});

// The closest hit of o + t·d, t in (t_min, t_max), in the set's coordinates, by the shader's
// algorithm over the packed words (castRayLooseKdTree): the reference the GPU is tested against.
gpu::RayCastHit castLooseKdTree(const LooseKdTree& tree, const IvmTriangleSet& set,
                                const glm::vec3& o, const glm::vec3& d, float t_min, float t_max);

// The tree on the GPU: node words as an R32UI buffer texture at kRayNodesUnit, flags as R8UI at
// kRayFlagsUnit, the triangles in triangle_order at kRayTrianglesUnit.
class GpuLooseKdTree final : public GpuRayStructure {
 public:
  explicit GpuLooseKdTree(const IvmTriangleSet& set, const LooseKdTreeSettings& settings = {});
  std::string_view name() const override { return "loose_kd_tree"; }
  std::string_view castFunction() const override { return "castRayLooseKdTree"; }
  void bind() const override;
  std::size_t bytes() const override;

  // The CPU tree it uploaded (its statistics, and castLooseKdTree in tests).
  const LooseKdTree& tree() const { return tree_; }

 private:
  LooseKdTree tree_;
  GpuRayTriangles triangles_;
  gl::Buffer node_buffer_, flag_buffer_;
  gl::Texture nodes_, flags_;
};

}  // namespace gib::rt
