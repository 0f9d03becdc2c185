#include "realtime/techniques/prt/prt_mesh.h"

#include "common/input_error.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace gib::rt::prt {

namespace {

// A lattice point's identity, so that the triangles sharing it share one vertex: an original
// vertex (a = b, s = 0), or step s of k along the edge from vertex a to vertex b (a < b), or an
// interior point (a = b = the triangle, s = its lattice index, interior = true). A flat mesh
// (no shading normals) keys its vertices by the triangle's quantised normal too, so that only
// coplanar triangles share them: a box's faces keep their own normals at its edges.
using LatticeKey =
    std::tuple<std::uint32_t, bool, std::uint32_t, std::uint32_t, std::uint32_t, int, int, int>;

glm::ivec3 quantised(const glm::vec3& n) {
  return glm::ivec3(glm::round(n * 1e4f));
}

int meshSubdivisions(const scene::Mesh& mesh, float max_edge) {
  double longest = 0;
  for (const glm::uvec3& t : mesh.triangles)
    for (int e = 0; e < 3; ++e)
      longest = std::max(
          longest, double(glm::length(mesh.positions[t[e]] - mesh.positions[t[(e + 1) % 3]])));
  return std::max(1, int(std::ceil(longest / double(max_edge))));
}

}  // namespace

PrtMesh tessellate(const scene::Scene& scene, float max_edge, std::size_t max_vertices) {
  if (!(max_edge > 0))
    throw InputError(fmt::format("technique 'prt': max_edge={} must be positive", max_edge));
  PrtMesh out;
  // Lattice points before merging, to refuse a runaway tessellation before it is built.
  std::size_t points = 0;
  for (const scene::Mesh& mesh : scene.meshes) {
    const int k = meshSubdivisions(mesh, max_edge);
    out.subdivisions.push_back(k);
    out.mesh_lattice_begin.push_back(points);
    points += mesh.triangles.size() * latticeSize(k);
  }
  if (points > 3 * max_vertices)
    throw InputError(fmt::format(
        "technique 'prt': max_edge={} m splits the scene into about {} vertices, more than the "
        "{} the technique allows; raise max_edge",
        max_edge, points / 3, max_vertices));
  out.lattice.resize(points);

  std::map<LatticeKey, std::uint32_t> merged;
  for (std::uint32_t m = 0; m < scene.meshes.size(); ++m) {
    const scene::Mesh& mesh = scene.meshes[m];
    const scene::Material& material = scene.materials[mesh.material];
    const bool smooth = !mesh.normals.empty();
    const int k = out.subdivisions[m];
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
      const glm::uvec3 v = mesh.triangles[t];
      const glm::vec3 cross = glm::cross(mesh.positions[v[1]] - mesh.positions[v[0]],
                                         mesh.positions[v[2]] - mesh.positions[v[0]]);
      const float cross_length = glm::length(cross);
      const glm::vec3 flat = cross_length > 0 ? cross / cross_length : glm::vec3(0.0f, 1.0f, 0.0f);
      const glm::ivec3 flat_key = smooth ? glm::ivec3(0) : quantised(flat);
      std::uint32_t* lattice =
          out.lattice.data() + out.mesh_lattice_begin[m] + std::size_t(t) * latticeSize(k);
      for (int j = 0; j <= k; ++j)
        for (int i = 0; i + j <= k; ++i) {
          // The point as the barycentric combination of at most two original vertices when it
          // lies on an edge, computed from the edge's lower-numbered end, so that both triangles
          // of the edge compute it bit for bit alike.
          std::uint32_t a, b, s;
          bool interior = false;
          const int w0 = k - i - j;
          if (i == 0 && j == 0) {
            a = b = v[0], s = 0;
          } else if (i == k) {
            a = b = v[1], s = 0;
          } else if (j == k) {
            a = b = v[2], s = 0;
          } else if (j == 0) {
            a = v[0], b = v[1], s = std::uint32_t(i);
          } else if (i == 0) {
            a = v[0], b = v[2], s = std::uint32_t(j);
          } else if (w0 == 0) {
            a = v[1], b = v[2], s = std::uint32_t(j);
          } else {
            a = b = t, s = std::uint32_t(latticeIndex(k, i, j)), interior = true;
          }
          if (a > b) std::swap(a, b), s = std::uint32_t(k) - s;
          const LatticeKey key{m, interior, a, b, s, flat_key.x, flat_key.y, flat_key.z};
          const auto [it, inserted] = merged.try_emplace(key, std::uint32_t(out.positions.size()));
          lattice[latticeIndex(k, i, j)] = it->second;
          if (!inserted) continue;
          glm::vec3 position, normal;
          if (interior) {
            const float f1 = float(i) / float(k), f2 = float(j) / float(k), f0 = 1.0f - f1 - f2;
            position =
                f0 * mesh.positions[v[0]] + f1 * mesh.positions[v[1]] + f2 * mesh.positions[v[2]];
            normal =
                smooth ? f0 * mesh.normals[v[0]] + f1 * mesh.normals[v[1]] + f2 * mesh.normals[v[2]]
                       : flat;
          } else {
            const float f = float(s) / float(k);
            position = (1.0f - f) * mesh.positions[a] + f * mesh.positions[b];
            normal = smooth ? (1.0f - f) * mesh.normals[a] + f * mesh.normals[b] : flat;
          }
          const float length = glm::length(normal);
          out.positions.push_back(position);
          out.normals.push_back(length > 0 ? normal / length : flat);
          out.albedo.push_back(material.diffuse);
        }
      for (int j = 0; j < k; ++j)
        for (int i = 0; i + j < k; ++i) {
          out.corners.insert(out.corners.end(),
                             {lattice[latticeIndex(k, i, j)], lattice[latticeIndex(k, i + 1, j)],
                              lattice[latticeIndex(k, i, j + 1)]});
          if (i + j + 1 < k)
            out.corners.insert(out.corners.end(), {lattice[latticeIndex(k, i + 1, j + 1)],
                                                   lattice[latticeIndex(k, i, j + 1)],
                                                   lattice[latticeIndex(k, i + 1, j)]});
        }
    }
  }
  if (out.positions.size() > max_vertices)
    throw InputError(fmt::format(
        "technique 'prt': max_edge={} m splits the scene into {} vertices, more than the {} the "
        "technique allows; raise max_edge",
        max_edge, out.positions.size(), max_vertices));
  return out;
}

LatticeHit locate(const PrtMesh& mesh, const scene::Scene& scene, std::uint32_t mesh_index,
                  std::uint32_t triangle, const glm::vec3& point) {
  const scene::Mesh& original = scene.meshes[mesh_index];
  const glm::uvec3 v = original.triangles[triangle];
  const glm::vec3 a = original.positions[v[0]];
  const glm::vec3 e1 = original.positions[v[1]] - a, e2 = original.positions[v[2]] - a;
  const glm::vec3 p = point - a;
  // Barycentrics of the point's projection onto the triangle's plane.
  const float d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
  const float p1 = glm::dot(p, e1), p2 = glm::dot(p, e2);
  const float det = d11 * d22 - d12 * d12;
  float w1 = det > 0 ? (d22 * p1 - d12 * p2) / det : 0.0f;
  float w2 = det > 0 ? (d11 * p2 - d12 * p1) / det : 0.0f;
  // A hit rounds a little off its triangle: back onto it.
  w1 = std::clamp(w1, 0.0f, 1.0f);
  w2 = std::clamp(w2, 0.0f, 1.0f);
  if (w1 + w2 > 1.0f) {
    const float sum = w1 + w2;
    w1 /= sum, w2 /= sum;
  }
  const int k = mesh.subdivisions[mesh_index];
  const float x = w1 * float(k), y = w2 * float(k);
  const int i = std::clamp(int(std::floor(x)), 0, k - 1);
  const int j = std::clamp(int(std::floor(y)), 0, k - 1 - i);
  float fx = x - float(i), fy = y - float(j);
  const std::uint32_t* lattice = mesh.lattice.data() + mesh.mesh_lattice_begin[mesh_index] +
                                 std::size_t(triangle) * latticeSize(k);
  LatticeHit hit;
  if (fx + fy > 1.0f && i + j + 1 < k) {
    // The upper sub-triangle (i+1, j+1), (i, j+1), (i+1, j).
    hit.vertices = {lattice[latticeIndex(k, i + 1, j + 1)], lattice[latticeIndex(k, i, j + 1)],
                    lattice[latticeIndex(k, i + 1, j)]};
    hit.weights = {fx + fy - 1.0f, 1.0f - fx, 1.0f - fy};
  } else {
    if (fx + fy > 1.0f) {  // past the last row's diagonal by rounding
      const float sum = fx + fy;
      fx /= sum, fy /= sum;
    }
    hit.vertices = {lattice[latticeIndex(k, i, j)], lattice[latticeIndex(k, i + 1, j)],
                    lattice[latticeIndex(k, i, j + 1)]};
    hit.weights = {1.0f - fx - fy, fx, fy};
  }
  return hit;
}

}  // namespace gib::rt::prt
