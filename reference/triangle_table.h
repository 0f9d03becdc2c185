// Per-triangle data the tracer needs at a hit (plane, area, material), flattened over meshes so
// that (mesh, triangle) and a global triangle index convert in O(1).
#pragma once

#include "scene/scene.h"

#include <glm/geometric.hpp>

#include <cstdint>
#include <vector>

namespace gib::ref {

struct TriangleRecord {
  glm::vec3 p0, e1, e2;  // vertex 0 and the edges to vertices 1 and 2
  glm::vec3 normal;      // unit front normal e1 × e2 / |e1 × e2|
  float area = 0;
  std::uint32_t material = 0;
  // Index of the triangle's three vertex normals in the table's normal list; kFlat when its mesh
  // has none (it is shaded with `normal`).
  static constexpr std::uint32_t kFlat = ~0u;
  std::uint32_t shading_normals = kFlat;

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

  // The shading normal at `point` of a triangle (docs/rendering.md, "Shading normals"): its
  // vertex normals interpolated by the point's barycentric coordinates, unit, on the front side;
  // the geometric normal for a flat triangle, or where the interpolation degenerates or leaves the
  // front hemisphere (a vertex normal pointing backwards would turn the surface inside out).
  glm::vec3 shadingNormal(const TriangleRecord& triangle, const glm::vec3& point) const;

  // A hit's normals turned towards `wo` (reflection is two-sided), and whether wo lies on the
  // front side (for glass, the outside).
  struct OrientedNormals {
    glm::vec3 geometric;
    glm::vec3 shading;
    bool front;
  };
  OrientedNormals orientedNormals(const TriangleRecord& triangle, const glm::vec3& point,
                                  const glm::vec3& wo) const {
    const bool front = glm::dot(triangle.normal, wo) >= 0;
    const glm::vec3 shading = shadingNormal(triangle, point);
    return {front ? triangle.normal : -triangle.normal, front ? shading : -shading, front};
  }

 private:
  std::vector<std::uint32_t> mesh_offsets_;
  std::vector<TriangleRecord> triangles_;
  std::vector<glm::vec3> normals_;  // three per smooth triangle
};

}  // namespace gib::ref
