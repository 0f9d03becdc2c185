#include "realtime/atlas/atlas_mesh.h"

#include "realtime/gl/gpu_commands.h"
#include "realtime/gpu_scene/gpu_scene.h"

#include <cstddef>
#include <cstdint>

namespace gib::rt::atlas {

namespace {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  std::uint32_t material;
  glm::vec2 uv;
};
static_assert(sizeof(Vertex) == 36, "Vertex must be tightly packed");

struct Corner {
  glm::vec3 position;
  glm::vec2 uv;
};

Corner midpoint(const Corner& a, const Corner& b) {
  return {0.5f * (a.position + b.position), 0.5f * (a.uv + b.uv)};
}

void emitTessellated(const Corner& a, const Corner& b, const Corner& c, int levels,
                     const glm::vec3& normal, std::uint32_t material, std::vector<Vertex>& out) {
  if (levels == 0) {
    for (const Corner* k : {&a, &b, &c}) out.push_back({k->position, normal, material, k->uv});
    return;
  }
  const Corner ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
  emitTessellated(a, ab, ca, levels - 1, normal, material, out);
  emitTessellated(ab, b, bc, levels - 1, normal, material, out);
  emitTessellated(ca, bc, c, levels - 1, normal, material, out);
  emitTessellated(ab, bc, ca, levels - 1, normal, material, out);
}

}  // namespace

AtlasMesh::AtlasMesh(const std::vector<AtlasTriangle>& triangles, const AtlasLayout& layout,
                     int tessellation_levels) {
  std::vector<Vertex> vertices;
  const float to_uv = 1.0f / float(layout.resolution);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (layout.chart_of_triangle[t] < 0) continue;  // degenerate: never rasterised
    const AtlasTriangle& tri = triangles[t];
    const auto& uv = layout.texel_coordinates[t];
    emitTessellated({tri.p[0], uv[0] * to_uv}, {tri.p[1], uv[1] * to_uv}, {tri.p[2], uv[2] * to_uv},
                    tessellation_levels, tri.normal, tri.material, vertices);
  }
  vertex_count_ = vertices.size();
  vertices_ = gl::Buffer::fromVector(vertices, 0);
  setSceneVertexAttributes<Vertex>(vertex_array_, vertices_);
  const GLuint vao = vertex_array_.id();
  glVertexArrayAttribFormat(vao, gpu::kVertexAtlasUvLocation, 2, GL_FLOAT, GL_FALSE,
                            offsetof(Vertex, uv));
  glVertexArrayAttribBinding(vao, gpu::kVertexAtlasUvLocation, 0);
  glEnableVertexArrayAttrib(vao, gpu::kVertexAtlasUvLocation);
}

void AtlasMesh::draw(int instances) const {
  if (vertex_count_ == 0 || instances <= 0) return;
  vertex_array_.bind();
  if (instances == 1)
    gl::drawArrays(GL_TRIANGLES, 0, GLsizei(vertex_count_));
  else
    gl::drawArraysInstanced(GL_TRIANGLES, 0, GLsizei(vertex_count_), instances);
}

}  // namespace gib::rt::atlas
