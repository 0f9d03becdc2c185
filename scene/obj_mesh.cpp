#include "scene/obj_mesh.h"

#include <fmt/format.h>
#include <tiny_obj_loader.h>
#include <glm/geometric.hpp>

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace gib::scene {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kReexport = "fix or re-export the OBJ file";

// The text of the OBJ file at `path`; `where` is the `file` value, for errors.
std::string readObjText(const SceneTableReader& t, const toml::node& where, const fs::path& path) {
  const std::string key = t.path("file");
  const std::string fix = "check the path (a relative path starts at the scene file's folder)";
  std::error_code ec;
  if (!fs::exists(path, ec))
    t.errors().fail(where, fmt::format("OBJ file '{}' ({}) does not exist", path.string(), key),
                    fix);
  if (!fs::is_regular_file(path, ec))
    t.errors().fail(where, fmt::format("OBJ path '{}' ({}) is not a file", path.string(), key),
                    fix);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  if (in.is_open()) text << in.rdbuf();
  if (!in.is_open() || in.bad())
    t.errors().fail(where, fmt::format("cannot read OBJ file '{}' ({})", path.string(), key),
                    "check the file's permissions");
  return text.str();
}

// The triangles' corners as tinyobj indexes them (position and normal index per corner), three
// per triangle, in the order of the file.
std::vector<tinyobj::index_t> triangleCorners(const tinyobj::ObjReader& reader) {
  std::vector<tinyobj::index_t> corners;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    std::size_t first = 0;
    for (unsigned int count : shape.mesh.num_face_vertices) {
      // Already triangles after triangulation; a fan keeps any other polygon whole.
      for (unsigned int k = 1; k + 1 < count; ++k)
        for (unsigned int c : {0u, k, k + 1}) corners.push_back(shape.mesh.indices[first + c]);
      first += count;
    }
  }
  return corners;
}

// The OBJ's `vn` lines as unit vectors; a zero or non-finite one is an error.
std::vector<glm::vec3> readNormals(const SceneTableReader& t, const toml::node& where,
                                   const fs::path& path, const tinyobj::attrib_t& attrib) {
  std::vector<glm::vec3> normals;
  const std::vector<tinyobj::real_t>& n = attrib.normals;
  for (std::size_t i = 0; i + 2 < n.size(); i += 3) {
    const glm::vec3 v(n[i], n[i + 1], n[i + 2]);
    if (!isFiniteVec3(v) || !(glm::length(v) > 0))
      t.errors().fail(where,
                      fmt::format("OBJ file '{}' ({}) has a zero or non-finite normal at vn line "
                                  "{}",
                                  path.string(), t.path("file"), normals.size() + 1),
                      kReexport);
    normals.push_back(glm::normalize(v));
  }
  return normals;
}

}  // namespace

Mesh loadObjMesh(const SceneTableReader& t, const toml::node& where, const fs::path& path,
                 bool read_normals) {
  const std::string key = t.path("file");
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  // From a string with an empty material library: the OBJ's own materials are never read.
  if (!reader.ParseFromString(readObjText(t, where, path), "", config))
    t.errors().fail(where,
                    fmt::format("OBJ file '{}' ({}) is malformed: {}", path.string(), key,
                                oneLine(reader.Error())),
                    kReexport);

  std::vector<glm::vec3> positions;
  const std::vector<tinyobj::real_t>& v = reader.GetAttrib().vertices;
  for (std::size_t i = 0; i + 2 < v.size(); i += 3) {
    positions.emplace_back(v[i], v[i + 1], v[i + 2]);
    if (!isFiniteVec3(positions.back()))
      t.errors().fail(where,
                      fmt::format("OBJ file '{}' ({}) has a non-finite position at vertex {}",
                                  path.string(), key, positions.size()),
                      kReexport);
  }
  const std::vector<tinyobj::index_t> corners = triangleCorners(reader);
  if (corners.empty())
    t.errors().fail(where, fmt::format("OBJ file '{}' ({}) has no triangles", path.string(), key),
                    "give the OBJ file at least one face ('f' line) of 3 or more vertices");
  for (const tinyobj::index_t& corner : corners)
    if (corner.vertex_index < 0 ||
        static_cast<std::size_t>(corner.vertex_index) >= positions.size())
      t.errors().fail(where,
                      fmt::format("OBJ file '{}' ({}) refers to vertex {} but has {} vertices",
                                  path.string(), key, corner.vertex_index + 1, positions.size()),
                      kReexport);

  bool has_normals = false;
  if (read_normals)
    for (const tinyobj::index_t& corner : corners) has_normals |= corner.normal_index >= 0;

  Mesh mesh;
  if (!has_normals) {
    // Flat: the OBJ's vertices as they are, unreferenced ones included.
    mesh.positions = std::move(positions);
    for (std::size_t i = 0; i < corners.size(); i += 3)
      mesh.triangles.emplace_back(corners[i].vertex_index, corners[i + 1].vertex_index,
                                  corners[i + 2].vertex_index);
    return mesh;
  }

  // Smooth: OBJ indexes positions and normals apart, per corner; a mesh has one normal per
  // vertex. Each distinct (position, normal) pair becomes one vertex, so every corner keeps its
  // exact normal (averaging the normals of a shared position would smooth over creases the file
  // marks by giving them different normals).
  const std::vector<glm::vec3> normals = readNormals(t, where, path, reader.GetAttrib());
  std::map<std::pair<int, int>, std::uint32_t> vertex_of;
  glm::uvec3 triangle{};
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const tinyobj::index_t& corner = corners[i];
    if (corner.normal_index < 0)
      t.errors().fail(where,
                      fmt::format("OBJ file '{}' ({}) gives some face corners a normal (vn) and "
                                  "others none, the first in triangle {}",
                                  path.string(), key, i / 3 + 1),
                      "give every corner a normal (f v//vn or f v/vt/vn), or none, or set smooth "
                      "= false to ignore them");
    if (static_cast<std::size_t>(corner.normal_index) >= normals.size())
      t.errors().fail(where,
                      fmt::format("OBJ file '{}' ({}) refers to normal {} but has {} normals (vn "
                                  "lines)",
                                  path.string(), key, corner.normal_index + 1, normals.size()),
                      kReexport);
    const auto [it, added] =
        vertex_of.try_emplace({corner.vertex_index, corner.normal_index},
                              static_cast<std::uint32_t>(mesh.positions.size()));
    if (added) {
      mesh.positions.push_back(positions[static_cast<std::size_t>(corner.vertex_index)]);
      mesh.normals.push_back(normals[static_cast<std::size_t>(corner.normal_index)]);
    }
    triangle[static_cast<int>(i % 3)] = it->second;
    if (i % 3 == 2) mesh.triangles.push_back(triangle);
  }
  return mesh;
}

}  // namespace gib::scene
