#include "scene/mesh_builder.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace gib::scene {

namespace {

// Smooth builders add a normal per vertex; a mesh that has vertices without normals would be left
// with normals that do not match its vertices.
void requireNormalsPerVertex(const Mesh& mesh, const char* builder) {
  if (mesh.normals.size() != mesh.positions.size())
    throw std::logic_error(std::string(builder) +
                           ": the mesh's vertex normals would not match its vertices");
}

}  // namespace

Mesh& addMeshOfMaterial(Scene& scene, std::string name, Material material) {
  scene.materials.push_back(std::move(material));
  Mesh mesh;
  mesh.name = std::move(name);
  mesh.material = static_cast<std::uint32_t>(scene.materials.size() - 1);
  scene.meshes.push_back(std::move(mesh));
  return scene.meshes.back();
}

void appendQuad(Mesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
  auto base = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), {a, b, c, d});
  mesh.triangles.push_back({base, base + 1, base + 2});
  mesh.triangles.push_back({base, base + 2, base + 3});
}

void appendSphere(Mesh& mesh, glm::vec3 centre, float radius, int rings, int segments, bool inward,
                  SphereShading shading) {
  const bool smooth = shading == SphereShading::kSmooth;
  if (smooth)
    requireNormalsPerVertex(mesh, "appendSphere");
  else if (!mesh.normals.empty())
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

void appendTorus(Mesh& mesh, glm::vec3 centre, glm::vec3 axis, float major_radius,
                 float minor_radius, int rings, int segments) {
  requireNormalsPerVertex(mesh, "appendTorus");
  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  const float pi = glm::pi<float>();
  // An orthonormal frame (e1, e2, a) around the axis: e1 along whichever world axis is least
  // parallel to it, so that the cross products stay well conditioned.
  const glm::vec3 a = glm::normalize(axis);
  const glm::vec3 helper = std::abs(a.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::vec3 e1 = glm::normalize(glm::cross(helper, a));
  const glm::vec3 e2 = glm::cross(a, e1);
  // Section r at angle φ about the axis; vertex s of it at angle θ around the tube, θ = 0 on the
  // outer equator. The normal at (φ, θ) is cos θ·radial(φ) + sin θ·a, the tube's own normal.
  for (int r = 0; r < rings; ++r) {
    const float phi = 2.0f * pi * float(r) / float(rings);
    const glm::vec3 radial = std::cos(phi) * e1 + std::sin(phi) * e2;
    for (int s = 0; s < segments; ++s) {
      const float theta = 2.0f * pi * float(s) / float(segments);
      const glm::vec3 normal = std::cos(theta) * radial + std::sin(theta) * a;
      mesh.positions.push_back(centre + major_radius * radial + minor_radius * normal);
      mesh.normals.push_back(normal);
    }
  }
  auto vertex = [&](int r, int s) {
    return base + std::uint32_t((r % rings) * segments + (s % segments));
  };
  // φ turns from e1 to e2 (counter-clockwise about a) and θ from the radial direction to a, so
  // ∂p/∂φ × ∂p/∂θ points along the normal: (r, s), (r+1, s), (r+1, s+1) faces outwards.
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      mesh.triangles.push_back({vertex(r, s), vertex(r + 1, s), vertex(r + 1, s + 1)});
      mesh.triangles.push_back({vertex(r, s), vertex(r + 1, s + 1), vertex(r, s + 1)});
    }
}

void appendParallelepiped(Mesh& mesh, glm::vec3 centre, glm::vec3 u, glm::vec3 v, glm::vec3 w) {
  if (!mesh.normals.empty())
    throw std::logic_error(
        "appendParallelepiped: the mesh's vertex normals would not match its vertices");
  // Left-handed edges would turn every face inwards: swap u and v to make them right-handed.
  if (glm::dot(glm::cross(u, v), w) < 0) std::swap(u, v);
  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  // Corner i is centre ± u ± v ± w, with bit 0 of i choosing +u, bit 1 +v and bit 2 +w.
  for (int i = 0; i < 8; ++i)
    mesh.positions.push_back(centre + ((i & 1) ? u : -u) + ((i & 2) ? v : -v) + ((i & 4) ? w : -w));
  // Each face as four corners wound counter-clockwise seen from outside (right-handed u, v, w).
  static constexpr std::uint32_t kFaces[6][4] = {
      {0, 4, 6, 2},  // −u
      {1, 3, 7, 5},  // +u
      {0, 1, 5, 4},  // −v
      {2, 6, 7, 3},  // +v
      {0, 2, 3, 1},  // −w
      {4, 5, 7, 6},  // +w
  };
  for (const auto& f : kFaces) {
    mesh.triangles.push_back({base + f[0], base + f[1], base + f[2]});
    mesh.triangles.push_back({base + f[0], base + f[2], base + f[3]});
  }
}

}  // namespace gib::scene
