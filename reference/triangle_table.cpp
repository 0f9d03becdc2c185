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
      if (!mesh.normals.empty()) {
        r.shading_normals = static_cast<std::uint32_t>(normals_.size());
        for (int k = 0; k < 3; ++k) normals_.push_back(mesh.normals[t[k]]);
      }
      triangles_.push_back(r);
    }
  }
}

glm::vec3 TriangleTable::shadingNormal(const TriangleRecord& tri, const glm::vec3& point) const {
  if (tri.shading_normals == TriangleRecord::kFlat) return tri.normal;
  // Barycentric coordinates of the point from the edge vectors (it lies in the plane up to float
  // error; the projection onto the plane is what the 2×2 system solves).
  const glm::vec3 d = point - tri.p0;
  const float d11 = glm::dot(tri.e1, tri.e1);
  const float d12 = glm::dot(tri.e1, tri.e2);
  const float d22 = glm::dot(tri.e2, tri.e2);
  const float det = d11 * d22 - d12 * d12;
  if (!(det > 0)) return tri.normal;
  const float p1 = glm::dot(d, tri.e1);
  const float p2 = glm::dot(d, tri.e2);
  const float b1 = (d22 * p1 - d12 * p2) / det;
  const float b2 = (d11 * p2 - d12 * p1) / det;
  const glm::vec3* n = &normals_[tri.shading_normals];
  const glm::vec3 interpolated = (1.0f - b1 - b2) * n[0] + b1 * n[1] + b2 * n[2];
  const float length = glm::length(interpolated);
  if (!(length > 0)) return tri.normal;
  const glm::vec3 unit = interpolated / length;
  return glm::dot(unit, tri.normal) > 0 ? unit : tri.normal;
}

}  // namespace gib::ref
