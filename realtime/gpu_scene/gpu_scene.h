// The scene model on the GPU, uploaded once: triangles (positions, geometric normals, material
// index per vertex, and the meshes' shading normals where a scene has them), the materials as a
// buffer texture, the camera as a uniform buffer, and the light lists on the CPU side for
// techniques that place shadow maps or samples.
// The layouts the shaders read (materials, camera block, vertex attributes) are declared once in
// gpu_scene_shared.h; scene.glsl and vertex.glsl are the GLSL side.
#pragma once

#include "realtime/gl/objects.h"
#include "realtime/gpu_scene/gpu_scene_shared.h"
#include "realtime/gpu_scene/view_culling.h"
#include "scene/scene.h"

#include <glm/mat4x4.hpp>

#include <cstddef>
#include <vector>

namespace gib::rt {

// Points the scene's vertex attributes (position, normal, material of gpu_scene_shared.h) of
// `vertex_array` at `buffer`, an array of `Vertex` records with members of those names, and
// enables them. Vertex arrays that add attributes (AtlasMesh) set those themselves.
template <typename Vertex>
void setSceneVertexAttributes(const gl::VertexArray& vertex_array, const gl::Buffer& buffer) {
  const GLuint vao = vertex_array.id();
  glVertexArrayVertexBuffer(vao, 0, buffer.id(), 0, sizeof(Vertex));
  glVertexArrayAttribFormat(vao, gpu::kVertexPositionLocation, 3, GL_FLOAT, GL_FALSE,
                            offsetof(Vertex, position));
  glVertexArrayAttribFormat(vao, gpu::kVertexNormalLocation, 3, GL_FLOAT, GL_FALSE,
                            offsetof(Vertex, normal));
  glVertexArrayAttribIFormat(vao, gpu::kVertexMaterialLocation, 1, GL_UNSIGNED_INT,
                             offsetof(Vertex, material));
  for (GLuint attribute :
       {gpu::kVertexPositionLocation, gpu::kVertexNormalLocation, gpu::kVertexMaterialLocation}) {
    glVertexArrayAttribBinding(vao, attribute, 0);
    glEnableVertexArrayAttrib(vao, attribute);
  }
}

// The GL camera of a pinhole camera::Camera: the same rays as scene::cameraRayDirection through
// every pixel centre. Near and far planes enclose the scene's bounds.
struct CameraTransform {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::vec3 position{0.0f};
  float near_plane = 0, far_plane = 0;
};
CameraTransform cameraTransform(const scene::Camera& camera, int width, int height,
                                const glm::vec3& bounds_min, const glm::vec3& bounds_max);

// An emissive triangle, in world space, for area-light sampling.
struct EmitterTriangle {
  glm::vec3 a, b, c;
  glm::vec3 normal;  // unit, front side (the side it emits to)
  float area;
  scene::Rgb emission;  // radiance
};

// The scene's emissive triangles in world space (degenerate ones, which emit nothing, left out).
std::vector<EmitterTriangle> emitterTriangles(const scene::Scene& scene);

class GpuScene {
 public:
  // Uploads geometry and materials and sets the camera for a width × height image.
  GpuScene(const scene::Scene& scene, int width, int height);

  const scene::Scene& scene() const { return *scene_; }
  int width() const { return width_; }
  int height() const { return height_; }
  glm::vec3 boundsMin() const { return bounds_min_; }
  glm::vec3 boundsMax() const { return bounds_max_; }
  const CameraTransform& camera() const { return camera_; }
  const std::vector<EmitterTriangle>& emitters() const { return emitters_; }
  std::size_t vertexCount() const { return vertex_count_; }

  // Binds the materials (a buffer texture) and the camera block to their unit and binding.
  void bindSceneBuffers() const;
  // Draws every triangle with the scene's vertex attributes (the caller has bound a program);
  // `instances` times in one command (gl_InstanceID tells them apart: layered rendering).
  void draw(int instances = 1) const;
  // The triangle list's chunks (view_culling.h), in the order draw() draws them.
  const std::vector<TriangleChunk>& chunks() const { return chunks_; }
  // Appends the records that draw the scene into one view of a multi-draw, `view` its index
  // there: with `cull`, the runs of chunks its frustum (and `keep`) may touch; else every
  // triangle (tests compare the two).
  void appendViewRecords(const glm::mat4& view_projection, GLuint view, bool cull,
                         std::vector<DrawArraysIndirectCommand>& records,
                         const glm::vec4& keep = kKeepEverything) const;
  // Draws `count` records (DrawArraysIndirectCommand, made by appendVisibleRuns) from byte
  // `offset` of buffer `records` in one multi-draw; each record's base instance reaches the
  // vertex shader as vertex_instance (kVertexInstanceLocation).
  void drawRecords(GLuint records, std::size_t offset, std::size_t count) const;

 private:
  const scene::Scene* scene_;
  int width_, height_;
  glm::vec3 bounds_min_, bounds_max_;
  CameraTransform camera_;
  std::vector<EmitterTriangle> emitters_;
  std::size_t vertex_count_ = 0;
  std::vector<TriangleChunk> chunks_;
  gl::Buffer vertices_, shading_normals_, instance_indices_, materials_, camera_block_;
  gl::Texture material_texels_;  // materials_ as the buffer texture shaders read
  gl::VertexArray vertex_array_;
};

}  // namespace gib::rt
