#include "realtime/gpu_scene/view_culling.h"

#include <glm/common.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace gib::rt {

std::vector<TriangleChunk> triangleChunks(std::span<const glm::vec3> positions,
                                          int triangles_per_chunk) {
  if (triangles_per_chunk < 1) throw std::invalid_argument("a chunk holds at least one triangle");
  std::vector<TriangleChunk> chunks;
  const std::size_t per_chunk = 3 * std::size_t(triangles_per_chunk);
  for (std::size_t first = 0; first < positions.size(); first += per_chunk) {
    const std::size_t end = std::min(positions.size(), first + per_chunk);
    TriangleChunk chunk;
    chunk.first_vertex = GLint(first);
    chunk.vertex_count = GLsizei(end - first);
    chunk.lo = chunk.hi = positions[first];
    for (std::size_t i = first + 1; i < end; ++i) {
      chunk.lo = glm::min(chunk.lo, positions[i]);
      chunk.hi = glm::max(chunk.hi, positions[i]);
    }
    chunks.push_back(chunk);
  }
  return chunks;
}

namespace {

// The seven planes a view keeps, as (n, d) with n·p + d ≥ 0 inside: the clip volume's as rows of
// the matrix, w ± x ≥ 0, w ± y ≥ 0, w ± z ≥ 0 (Gribb and Hartmann), and `keep`. In double, and
// made once per view rather than once per chunk.
struct ViewPlanes {
  std::array<glm::dvec4, 7> planes;
};

ViewPlanes viewPlanes(const glm::mat4& view_projection, const glm::vec4& keep) {
  const glm::dmat4 m(view_projection);
  const glm::dvec4 w(m[0][3], m[1][3], m[2][3], m[3][3]);
  ViewPlanes view;
  for (int axis = 0; axis < 3; ++axis) {
    const glm::dvec4 row(m[0][axis], m[1][axis], m[2][axis], m[3][axis]);
    view.planes[std::size_t(2 * axis)] = w + row;
    view.planes[std::size_t(2 * axis + 1)] = w - row;
  }
  view.planes[6] = glm::dvec4(keep);
  return view;
}

// With a margin of 1e-5 of the plane's size at the box: culling must never drop a triangle that
// rasterises, so rounding may only keep too much.
bool boxOutside(const ViewPlanes& view, const glm::vec3& lo, const glm::vec3& hi) {
  const glm::dvec3 box_lo(lo), box_hi(hi);
  const double extent = std::max({std::abs(box_lo.x), std::abs(box_lo.y), std::abs(box_lo.z),
                                  std::abs(box_hi.x), std::abs(box_hi.y), std::abs(box_hi.z), 1.0});
  for (const glm::dvec4& plane : view.planes) {
    // The box's corner farthest along the plane's normal: if even it is behind, all are.
    const glm::dvec3 corner(plane.x >= 0 ? box_hi.x : box_lo.x, plane.y >= 0 ? box_hi.y : box_lo.y,
                            plane.z >= 0 ? box_hi.z : box_lo.z);
    const double distance = plane.x * corner.x + plane.y * corner.y + plane.z * corner.z + plane.w;
    const double size =
        (std::abs(plane.x) + std::abs(plane.y) + std::abs(plane.z)) * extent + std::abs(plane.w);
    if (distance < -1e-5 * size) return true;
  }
  return false;
}

}  // namespace

bool boxOutsideFrustum(const glm::mat4& view_projection, const glm::vec3& lo, const glm::vec3& hi,
                       const glm::vec4& keep) {
  return boxOutside(viewPlanes(view_projection, keep), lo, hi);
}

void appendVisibleRuns(std::span<const TriangleChunk> chunks, const glm::mat4& view_projection,
                       GLuint view, std::vector<DrawArraysIndirectCommand>& commands,
                       const glm::vec4& keep) {
  const ViewPlanes planes = viewPlanes(view_projection, keep);
  bool in_run = false;
  for (const TriangleChunk& chunk : chunks) {
    if (boxOutside(planes, chunk.lo, chunk.hi)) {
      in_run = false;
      continue;
    }
    // Chunks are contiguous in the vertex buffer: a visible chunk after a visible one extends
    // its run.
    if (in_run) {
      commands.back().count += GLuint(chunk.vertex_count);
    } else {
      commands.push_back({GLuint(chunk.vertex_count), 1, GLuint(chunk.first_vertex), view});
      in_run = true;
    }
  }
}

}  // namespace gib::rt
