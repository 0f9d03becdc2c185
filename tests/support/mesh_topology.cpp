#include "support/mesh_topology.h"

#include <glm/geometric.hpp>

#include <array>
#include <map>
#include <utility>

namespace gib::test {

namespace {

using Point = std::array<float, 3>;
using Edge = std::pair<Point, Point>;

Point pointOf(const glm::vec3& p) {
  return {p.x, p.y, p.z};
}

}  // namespace

std::size_t unmatchedEdges(const std::vector<const scene::Mesh*>& meshes) {
  std::map<Edge, int> directed;
  for (const scene::Mesh* mesh : meshes)
    for (const glm::uvec3& t : mesh->triangles)
      for (int k = 0; k < 3; ++k)
        ++directed[{pointOf(mesh->positions[t[k]]), pointOf(mesh->positions[t[(k + 1) % 3]])}];
  std::size_t unmatched = 0;
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    if (count != 1 || reverse == directed.end() || reverse->second != 1) ++unmatched;
  }
  return unmatched;
}

double signedVolume(const std::vector<const scene::Mesh*>& meshes) {
  double volume = 0;
  for (const scene::Mesh* mesh : meshes)
    for (const glm::uvec3& t : mesh->triangles) {
      const glm::dvec3 a(mesh->positions[t[0]]), b(mesh->positions[t[1]]), c(mesh->positions[t[2]]);
      volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
  return volume;
}

}  // namespace gib::test
