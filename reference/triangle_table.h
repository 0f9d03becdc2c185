// Per-triangle data the tracer needs at a hit (plane, area, material), flattened over meshes so
// that (mesh, triangle) and a global triangle index convert in O(1).
#pragma once

#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace gib::ref {

struct TriangleRecord {
  glm::vec3 p0, e1, e2;  // vertex 0 and the edges to vertices 1 and 2
  glm::vec3 normal;      // unit front normal e1 × e2 / |e1 × e2|
  float area = 0;
  std::uint32_t material = 0;

  glm::vec3 point(float b1, float b2) const { return p0 + b1 * e1 + b2 * e2; }
};

class TriangleTable {
 public:
  explicit TriangleTable(const scene::Scene& scene);

  std::uint32_t globalIndex(std::uint32_t mesh, std::uint32_t triangle) const {
    return mesh_offsets_[mesh] + triangle;
  }
  const TriangleRecord& operator[](std::uint32_t global_index) const {
    return triangles_[global_index];
  }
  std::size_t size() const { return triangles_.size(); }

 private:
  std::vector<std::uint32_t> mesh_offsets_;
  std::vector<TriangleRecord> triangles_;
};

}  // namespace gib::ref
