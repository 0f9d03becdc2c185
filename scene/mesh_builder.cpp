#include "scene/mesh_builder.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <stdexcept>

namespace gib::scene {

void appendQuad(Mesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
  auto base = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), {a, b, c, d});
  mesh.triangles.push_back({base, base + 1, base + 2});
  mesh.triangles.push_back({base, base + 2, base + 3});
}

void appendSphere(Mesh& mesh, glm::vec3 centre, float radius, int rings, int segments, bool inward,
                  SphereShading shading) {
  const bool smooth = shading == SphereShading::kSmooth;
  if (smooth ? mesh.normals.size() != mesh.positions.size() : !mesh.normals.empty())
    throw std::logic_error("appendSphere: the mesh's vertex normals would not match its vertices");
  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  const float pi = glm::pi<float>();
  // Each vertex from its unit direction: the position on the sphere and, when smooth, the exact
  // normal there (the same direction, turned inwards with the triangles).
  auto addVertex = [&](glm::vec3 direction) {
    mesh.positions.push_back(centre + radius * direction);
    if (smooth) mesh.normals.push_back(inward ? -direction : direction);
  };
  // Vertex 0 is the north pole, then (rings − 1) rings of `segments` vertices, then the south pole.
  addVertex(glm::vec3(0, 1, 0));
  for (int r = 1; r < rings; ++r) {
    float theta = pi * float(r) / float(rings);
    for (int s = 0; s < segments; ++s) {
      float phi = 2.0f * pi * float(s) / float(segments);
      addVertex(glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                          -std::sin(theta) * std::sin(phi)));
    }
  }
  const auto south = static_cast<std::uint32_t>(mesh.positions.size());
  addVertex(glm::vec3(0, -1, 0));

  auto ring = [&](int r, int s) {
    return base + 1 + std::uint32_t((r - 1) * segments + (s % segments));
  };
  // Outward winding: with φ increasing counter-clockwise seen from above (−sin φ on z), the
  // triangle (upper, lower, lower-next) has an outward normal.
  auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (inward)
      mesh.triangles.push_back({a, c, b});
    else
      mesh.triangles.push_back({a, b, c});
  };
  for (int s = 0; s < segments; ++s) add(base, ring(1, s), ring(1, s + 1));
  for (int r = 1; r + 1 < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      add(ring(r, s), ring(r + 1, s), ring(r + 1, s + 1));
      add(ring(r, s), ring(r + 1, s + 1), ring(r, s + 1));
    }
  for (int s = 0; s < segments; ++s) add(ring(rings - 1, s), south, ring(rings - 1, s + 1));
}

}  // namespace gib::scene
