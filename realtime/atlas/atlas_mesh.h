// The scene's triangles with their atlas coordinates, optionally tessellated, for the draws of
// atlas techniques (the camera view that looks the atlas up, the visibility maps of a shooter).
// Tessellation splits every triangle into four per level (midpoints; atlas coordinates
// interpolated), so the surfaces and the atlas stay the same and only the vertex count changes:
// the hemispherical projection's accuracy and the cost of geometry passes depend on it.
//
// Vertex attributes (atlas/atlas_vertex.glsl): the scene's (gpu_scene/gpu_scene_shared.h) and
// the atlas coordinate in [0, 1]² at kVertexAtlasUvLocation.
#pragma once

#include "realtime/atlas/atlas_layout.h"
#include "realtime/gl/objects.h"

namespace gib::rt::atlas {

class AtlasMesh {
 public:
  AtlasMesh(const std::vector<AtlasTriangle>& triangles, const AtlasLayout& layout,
            int tessellation_levels);

  std::size_t vertexCount() const { return vertex_count_; }
  // `instances` times in one command (gl_InstanceID tells them apart: layered rendering).
  void draw(int instances = 1) const;

 private:
  std::size_t vertex_count_ = 0;
  gl::Buffer vertices_;
  gl::VertexArray vertex_array_;
};

}  // namespace gib::rt::atlas
