#include "reference/triangle_table.h"

#include <glm/geometric.hpp>

namespace gib::ref {

TriangleTable::TriangleTable(const scene::Scene& scene) {
  for (const scene::Mesh& mesh : scene.meshes) {
    mesh_offsets_.push_back(static_cast<std::uint32_t>(triangles_.size()));
    for (const glm::uvec3& t : mesh.triangles) {
      TriangleRecord r;
      r.p0 = mesh.positions[t[0]];
      r.e1 = mesh.positions[t[1]] - r.p0;
      r.e2 = mesh.positions[t[2]] - r.p0;
      glm::vec3 c = glm::cross(r.e1, r.e2);
      float twice_area = glm::length(c);
      r.area = 0.5f * twice_area;
      // A degenerate triangle is never hit and never sampled (zero area); give it any normal.
      r.normal = twice_area > 0 ? c / twice_area : glm::vec3(0, 0, 1);
      r.material = mesh.material;
      triangles_.push_back(r);
    }
  }
}

}  // namespace gib::ref
