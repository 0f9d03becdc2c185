// Per-view culling of the scene's triangles for draws into many views at once (the irradiance
// volume's 384 probe cube faces): the triangle list is cut into chunks of consecutive triangles
// with their bounding boxes, and each view draws only the runs of chunks its frustum may touch,
// through one multi-draw whose records name the view by their base instance. A 90° cube face
// sees about a sixth of a scene around it, and a software rasteriser transforms every vertex of
// every view on one thread, so this is most of the probe views' cost there.
//
// Culling is conservative and keeps each view's triangles in their order, so the pixels drawn are
// those of the whole scene drawn into the view (a test compares them bit for bit).
#pragma once

#include "realtime/gl/gl.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace gib::rt {

// Consecutive triangles of a non-indexed triangle list, and the box around their vertices.
struct TriangleChunk {
  GLint first_vertex = 0;
  GLsizei vertex_count = 0;
  glm::vec3 lo{0.0f}, hi{0.0f};
};

// Triangles per chunk: small enough to cull a cube face's unseen five sixths of a 3 000-triangle
// hall, large enough that the runs a view draws stay few (each is a draw for the driver).
inline constexpr int kTrianglesPerChunk = 64;

// The chunks of a triangle list given by its vertex positions (three per triangle).
std::vector<TriangleChunk> triangleChunks(std::span<const glm::vec3> positions,
                                          int triangles_per_chunk = kTrianglesPerChunk);

// A plane that keeps everything: what a view without a clip plane of its own passes.
inline constexpr glm::vec4 kKeepEverything{0.0f, 0.0f, 0.0f, 1.0f};

// True when no point of the box [lo, hi] lies in the clip volume of `view_projection` (−w ≤ x,
// y, z ≤ w) on the side dot(plane, (p, 1)) ≥ 0 of `keep` (a user clip plane the view's draw
// applies): the box lies wholly outside one of these seven planes, with a margin against
// rounding.
bool boxOutsideFrustum(const glm::mat4& view_projection, const glm::vec3& lo, const glm::vec3& hi,
                       const glm::vec4& keep = kKeepEverything);

// GL's DrawArraysIndirectCommand, the record an indirect multi-draw of arrays reads (GL 4.5
// §10.4).
struct DrawArraysIndirectCommand {
  GLuint count = 0;
  GLuint instance_count = 0;
  GLuint first = 0;
  GLuint base_instance = 0;
};

// Appends one record per run of consecutive chunks not outside the view's frustum (and `keep`),
// each one instance with base instance `view` (the view's index within its draw).
void appendVisibleRuns(std::span<const TriangleChunk> chunks, const glm::mat4& view_projection,
                       GLuint view, std::vector<DrawArraysIndirectCommand>& commands,
                       const glm::vec4& keep = kKeepEverything);

}  // namespace gib::rt
