#include "realtime/gpu_scene/gpu_scene.h"

#include "realtime/gl/gpu_commands.h"
#include "scene/camera.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace gib::rt {

namespace {

// The vertex attributes of gpu_scene_shared.h: flat triangles, so every vertex carries its
// triangle's normal and material. Shading normals, which most scenes lack, live in a buffer of
// their own (GpuScene::GpuScene).
struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  std::uint32_t material;
};
static_assert(sizeof(Vertex) == 28, "Vertex must be tightly packed");

// The unnormalised geometric normal (b − a) × (c − a): its direction is the front side, its length
// twice the area.
glm::vec3 triangleCross(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  return glm::cross(b - a, c - a);
}

glm::vec3 unitOrZero(const glm::vec3& v) {
  const float length = glm::length(v);
  return length > 0 ? v / length : glm::vec3(0.0f);  // degenerate triangles are never rasterised
}

struct Bounds {
  glm::vec3 min{std::numeric_limits<float>::infinity()};
  glm::vec3 max{-std::numeric_limits<float>::infinity()};
  bool empty() const { return min.x > max.x; }
  void add(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
};

// Every mesh vertex and every medium particle's sphere. A scene with neither (nothing to see) gets
// a unit box around its camera, so that the camera still has valid clip planes.
Bounds sceneBounds(const scene::Scene& scene) {
  Bounds bounds;
  for (const scene::Mesh& mesh : scene.meshes)
    for (const glm::vec3& p : mesh.positions) bounds.add(p);
  for (const scene::MediumParticle& particle : scene.medium.particles) {
    bounds.add(particle.centre - glm::vec3(particle.radius));
    bounds.add(particle.centre + glm::vec3(particle.radius));
  }
  if (bounds.empty()) {
    bounds.add(scene.camera.position - glm::vec3(1.0f));
    bounds.add(scene.camera.position + glm::vec3(1.0f));
  }
  return bounds;
}

std::vector<Vertex> flatVertices(const scene::Scene& scene) {
  std::vector<Vertex> vertices;
  vertices.reserve(3 * scene.triangleCount());
  for (const scene::Mesh& mesh : scene.meshes)
    for (const glm::uvec3& t : mesh.triangles) {
      const glm::vec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
      const glm::vec3 normal = unitOrZero(triangleCross(a, b, c));
      for (const glm::vec3& p : {a, b, c}) vertices.push_back({p, normal, mesh.material});
    }
  return vertices;
}

// kVertexShadingNormalLocation's values, in flatVertices' order: each vertex's normal on a mesh
// that has them, zero on a flat one; empty when no mesh has them.
std::vector<glm::vec3> shadingNormals(const scene::Scene& scene) {
  if (std::none_of(scene.meshes.begin(), scene.meshes.end(),
                   [](const scene::Mesh& mesh) { return !mesh.normals.empty(); }))
    return {};
  std::vector<glm::vec3> normals;
  normals.reserve(3 * scene.triangleCount());
  for (const scene::Mesh& mesh : scene.meshes)
    for (const glm::uvec3& t : mesh.triangles)
      for (int k = 0; k < 3; ++k)
        normals.push_back(mesh.normals.empty() ? glm::vec3(0.0f) : mesh.normals[t[k]]);
  return normals;
}

int gpuMaterialType(scene::MaterialType type) {
  switch (type) {
    case scene::MaterialType::kLambert:
      return gpu::kMaterialLambert;
    case scene::MaterialType::kPhong:
      return gpu::kMaterialPhong;
    case scene::MaterialType::kMirror:
      return gpu::kMaterialMirror;
    case scene::MaterialType::kGlass:
      return gpu::kMaterialGlass;
  }
  return gpu::kMaterialLambert;
}

std::vector<gpu::Material> gpuMaterials(const scene::Scene& scene) {
  std::vector<gpu::Material> materials;
  materials.reserve(scene.materials.size());
  for (const scene::Material& m : scene.materials)
    materials.push_back({glm::vec4(m.diffuse, float(gpuMaterialType(m.type))),
                         glm::vec4(m.specular, m.exponent), glm::vec4(m.emission, 0.0f),
                         glm::vec4(m.conductor_n, m.perfect_mirror ? 1.0f : 0.0f),
                         glm::vec4(m.conductor_k, 0.0f), glm::vec4(m.absorption, m.ior)});
  return materials;
}

gpu::Camera cameraBlock(const CameraTransform& camera, int width, int height) {
  gpu::Camera block;
  block.view_projection = camera.projection * camera.view;
  block.view = camera.view;
  block.projection = camera.projection;
  block.position = glm::vec4(camera.position, 1.0f);
  block.near_far = glm::vec4(camera.near_plane, camera.far_plane, 0.0f, 0.0f);
  block.image_size =
      glm::vec4(float(width), float(height), 1.0f / float(width), 1.0f / float(height));
  return block;
}

}  // namespace

std::vector<EmitterTriangle> emitterTriangles(const scene::Scene& scene) {
  std::vector<EmitterTriangle> emitters;
  for (const scene::Mesh& mesh : scene.meshes) {
    const scene::Material& material = scene.materials[mesh.material];
    if (!material.isEmissive()) continue;
    for (const glm::uvec3& t : mesh.triangles) {
      const glm::vec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
      const glm::vec3 cross = triangleCross(a, b, c);
      const float twice_area = glm::length(cross);
      if (twice_area <= 0) continue;  // emits nothing, and has no normal to sample with
      emitters.push_back({a, b, c, cross / twice_area, 0.5f * twice_area, material.emission});
    }
  }
  return emitters;
}

CameraTransform cameraTransform(const scene::Camera& camera, int width, int height,
                                const glm::vec3& bounds_min, const glm::vec3& bounds_max) {
  // The frame of scene::cameraRayDirection, so that both share every rounding of the basis.
  const scene::CameraFrame frame = scene::makeCameraFrame(camera, width, height);
  const glm::dvec3 right(frame.right), up(frame.up), forward(frame.forward), eye(frame.origin);

  // View space: x along `right`, y along `up`, z along −forward. GL's window y grows upwards and
  // the image's rows downwards, so `up` (towards image row 0) ends on GL's top row, which
  // readPixels' row flip makes image row 0: the image is not mirrored.
  glm::dmat4 view(1.0);
  for (int i = 0; i < 3; ++i) {
    view[i][0] = right[i];
    view[i][1] = up[i];
    view[i][2] = -forward[i];
  }
  view[3] = glm::dvec4(-glm::dot(right, eye), -glm::dot(up, eye), glm::dot(forward, eye), 1.0);

  // Near plane: no visible bound point is closer along `forward` than its distance from the eye
  // times the cosine of the angle to the frustum's corner ray. A camera inside the bounds falls
  // back to 1e-4 of the extent: with DEPTH32F, depths still resolve to ~6e-4 of the distance at
  // the far end (the resolution is ~6e-8·z/near relative).
  const glm::dvec3 lo(bounds_min), hi(bounds_max);
  const double extent = std::max(glm::length(hi - lo), 1e-6);
  const double tan_y = frame.tan_half_fov_y, tan_x = tan_y * double(frame.aspect);
  const double cos_corner = 1.0 / std::sqrt(1.0 + tan_x * tan_x + tan_y * tan_y);
  const double distance_to_bounds = glm::length(glm::clamp(eye, lo, hi) - eye);
  const double near_plane = std::max(1e-4 * extent, 0.99 * distance_to_bounds * cos_corner);
  // Far plane: a little past the farthest corner (a distance bounds the depth along `forward`).
  const glm::dvec3 farthest = glm::max(glm::abs(lo - eye), glm::abs(hi - eye));
  const double far_plane = std::max(1.01 * glm::length(farthest), 2.0 * near_plane);

  // The symmetric perspective whose clip-space x/w and y/w are exactly ndc_x and ndc_y of
  // cameraRayDirection: the frame's own tangent and aspect, not glm::perspective's recomputation.
  glm::dmat4 projection(0.0);
  projection[0][0] = 1.0 / tan_x;
  projection[1][1] = 1.0 / tan_y;
  projection[2][2] = -(far_plane + near_plane) / (far_plane - near_plane);
  projection[2][3] = -1.0;
  projection[3][2] = -2.0 * far_plane * near_plane / (far_plane - near_plane);

  CameraTransform transform;
  transform.view = glm::mat4(view);
  transform.projection = glm::mat4(projection);
  transform.position = frame.origin;
  transform.near_plane = float(near_plane);
  transform.far_plane = float(far_plane);
  return transform;
}

GpuScene::GpuScene(const scene::Scene& scene, int width, int height)
    : scene_(&scene), width_(width), height_(height) {
  const Bounds bounds = sceneBounds(scene);
  bounds_min_ = bounds.min;
  bounds_max_ = bounds.max;
  camera_ = cameraTransform(scene.camera, width, height, bounds_min_, bounds_max_);
  emitters_ = emitterTriangles(scene);

  const std::vector<Vertex> vertices = flatVertices(scene);
  vertex_count_ = vertices.size();
  vertices_ = gl::Buffer::fromVector(vertices, 0);
  materials_ = gl::Buffer::fromVector(gpuMaterials(scene), 0);
  material_texels_ = gl::Texture::makeBuffer(GL_RGBA32F, materials_);
  const gpu::Camera block = cameraBlock(camera_, width, height);
  camera_block_ = gl::Buffer(sizeof(block), &block, 0);
  setSceneVertexAttributes<Vertex>(vertex_array_, vertices_);
  // Shading normals come from a second buffer, and only for a scene that has some: a flat scene
  // draws from the same vertex buffer as before they existed, and its disabled attribute reads
  // zero (GL's default current value), which shaders take as flat (shading_normal.glsl).
  const GLuint vao = vertex_array_.id();
  const std::vector<glm::vec3> shading_normals = shadingNormals(scene);
  if (!shading_normals.empty()) {
    shading_normals_ = gl::Buffer::fromVector(shading_normals, 0);
    glVertexArrayVertexBuffer(vao, 2, shading_normals_.id(), 0, sizeof(glm::vec3));
    glVertexArrayAttribFormat(vao, gpu::kVertexShadingNormalLocation, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao, gpu::kVertexShadingNormalLocation, 2);
    glEnableVertexArrayAttrib(vao, gpu::kVertexShadingNormalLocation);
  }

  std::vector<glm::vec3> positions;
  positions.reserve(vertices.size());
  for (const Vertex& v : vertices) positions.push_back(v.position);
  chunks_ = triangleChunks(positions);
  // The instance attribute holds 0, 1, 2, … per instance: a record drawn with base instance b
  // reads b (GL fetches instanced attributes from the base instance on).
  std::vector<GLuint> indices(gpu::kMaxVertexInstances);
  for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = GLuint(i);
  instance_indices_ = gl::Buffer::fromVector(indices, 0);
  glVertexArrayVertexBuffer(vao, 1, instance_indices_.id(), 0, sizeof(GLuint));
  glVertexArrayBindingDivisor(vao, 1, 1);
  glVertexArrayAttribIFormat(vao, gpu::kVertexInstanceLocation, 1, GL_UNSIGNED_INT, 0);
  glVertexArrayAttribBinding(vao, gpu::kVertexInstanceLocation, 1);
  glEnableVertexArrayAttrib(vao, gpu::kVertexInstanceLocation);
}

void GpuScene::bindSceneBuffers() const {
  material_texels_.bind(gpu::kMaterialsUnit);
  camera_block_.bindBase(GL_UNIFORM_BUFFER, gpu::kCameraBinding);
}

void GpuScene::draw(int instances) const {
  if (vertex_count_ == 0 || instances <= 0) return;
  vertex_array_.bind();
  gl::drawArraysInstanced(GL_TRIANGLES, 0, GLsizei(vertex_count_), instances);
}

void GpuScene::appendViewRecords(const glm::mat4& view_projection, GLuint view, bool cull,
                                 std::vector<DrawArraysIndirectCommand>& records,
                                 const glm::vec4& keep) const {
  if (cull)
    appendVisibleRuns(chunks_, view_projection, view, records, keep);
  else if (vertex_count_ > 0)
    records.push_back({GLuint(vertex_count_), 1, 0, view});
}

void GpuScene::drawRecords(GLuint records, std::size_t offset, std::size_t count) const {
  if (count == 0) return;
  vertex_array_.bind();
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, records);
  gl::multiDrawArraysIndirect(GL_TRIANGLES, offset, GLsizei(count));
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

}  // namespace gib::rt
