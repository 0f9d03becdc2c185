// The vertices per-vertex PRT shades (book §8.3): every mesh of the scene re-tessellated regularly,
// each triangle into k² sub-triangles on the lattice of barycentrics (i/k, j/k), so that a point
// the ray caster finds on an original triangle lies in a known sub-triangle with known vertices
// (a scene's large triangles, the outdoor ground's two, would otherwise carry two or three
// transfer vectors for metres of surface). One k per mesh, the largest any of its triangles needs
// for edges of at most `max_edge`, so that neighbouring triangles split their shared edge at the
// same points and the lattice vertices there are merged: the transfer is continuous across the
// original edges (README.md, "Vertices").
#pragma once

#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace gib::rt::prt {

struct PrtMesh {
  std::vector<glm::vec3> positions;    // per vertex, world space
  std::vector<glm::vec3> normals;      // per vertex, unit, the mesh's front side
  std::vector<glm::vec3> albedo;       // per vertex: the material's diffuse reflectance ρ
  std::vector<std::uint32_t> corners;  // 3 per sub-triangle: vertex indices

  // Per mesh of the scene: its k, and where its triangles' lattices start in `lattice`.
  std::vector<int> subdivisions;
  std::vector<std::size_t> mesh_lattice_begin;
  // Per original triangle, (k+1)(k+2)/2 vertex indices, lattice point (i, j) (barycentric i/k of
  // the triangle's second vertex, j/k of its third) at row-major position latticeIndex(k, i, j).
  std::vector<std::uint32_t> lattice;

  std::size_t vertexCount() const { return positions.size(); }
  std::size_t triangleCount() const { return corners.size() / 3; }
};

// Lattice points of one triangle split k times along each edge.
constexpr std::size_t latticeSize(int k) {
  return std::size_t(k + 1) * std::size_t(k + 2) / 2;
}
// Point (i, j), i + j ≤ k: rows of constant j, each k + 1 − j long.
constexpr std::size_t latticeIndex(int k, int i, int j) {
  return std::size_t(j) * std::size_t(k + 1) - std::size_t(j) * std::size_t(j - 1) / 2 +
         std::size_t(i);
}

// Throws gib::InputError for max_edge ≤ 0 or a tessellation of more than `max_vertices` vertices
// (naming max_edge and the count, so that the user can raise it).
PrtMesh tessellate(const scene::Scene& scene, float max_edge, std::size_t max_vertices);

// Where a point of original triangle `triangle` of mesh `mesh` lies: the three vertices of its
// sub-triangle and their linear weights (summing to 1).
struct LatticeHit {
  std::array<std::uint32_t, 3> vertices{};
  std::array<float, 3> weights{};
};
LatticeHit locate(const PrtMesh& mesh, const scene::Scene& scene, std::uint32_t mesh_index,
                  std::uint32_t triangle, const glm::vec3& point);

}  // namespace gib::rt::prt
