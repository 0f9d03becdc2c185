#include "realtime/distance_map/distance_maps.h"

#include "realtime/cube_faces.h"
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/shader_library.h"
#include "realtime/gpu_scene/gpu_scene.h"

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace gib::rt {

namespace {

GLuint groups(int texels) {
  return GLuint((texels + gpu::kDistanceMapGroupSize - 1) / gpu::kDistanceMapGroupSize);
}

}  // namespace

DistanceMapObject meshObject(const scene::Scene& scene, std::size_t mesh) {
  if (mesh >= scene.meshes.size())
    throw std::logic_error(fmt::format("mesh {} of {}", mesh, scene.meshes.size()));
  DistanceMapObject object;
  object.mesh = mesh;
  for (std::size_t m = 0; m < mesh; ++m)
    object.first_triangle += int(scene.meshes[m].triangles.size());
  const scene::Mesh& chosen = scene.meshes[mesh];
  object.end_triangle = object.first_triangle + int(chosen.triangles.size());
  object.bounds_min = glm::vec3(std::numeric_limits<float>::max());
  object.bounds_max = glm::vec3(std::numeric_limits<float>::lowest());
  for (const glm::uvec3& t : chosen.triangles)
    for (int k = 0; k < 3; ++k) {
      object.bounds_min = glm::min(object.bounds_min, chosen.positions[t[k]]);
      object.bounds_max = glm::max(object.bounds_max, chosen.positions[t[k]]);
    }
  object.reference_point = 0.5f * (object.bounds_min + object.bounds_max);
  return object;
}

std::vector<DistanceMapObject> specularObjects(const scene::Scene& scene) {
  std::vector<DistanceMapObject> objects;
  for (std::size_t m = 0; m < scene.meshes.size(); ++m)
    if (!scene.meshes[m].triangles.empty() &&
        scene::isIdealSpecular(scene.materials[scene.meshes[m].material].type))
      objects.push_back(meshObject(scene, m));
  return objects;
}

image::Image objectPixels(const GBuffer& camera, const std::vector<DistanceMapObject>& objects) {
  const image::Image codes = gl::readTexture(camera.albedo(), 4);
  image::Image mask(codes.width(), codes.height(), 1);
  for (int y = 0; y < codes.height(); ++y)
    for (int x = 0; x < codes.width(); ++x) {
      const int triangle = int(std::abs(codes.pixel(x, y)[3])) - 1;  // −1: background
      for (const DistanceMapObject& object : objects)
        if (triangle >= object.first_triangle && triangle < object.end_triangle)
          mask.pixel(x, y)[0] = 1.0f;
    }
  return mask;
}

void placeReferencePoints(std::vector<DistanceMapObject>& objects, ReferencePoint where,
                          const glm::vec3& scene_min, const glm::vec3& scene_max) {
  for (DistanceMapObject& object : objects)
    object.reference_point = where == ReferencePoint::kSceneCentre
                                 ? 0.5f * (scene_min + scene_max)
                                 : 0.5f * (object.bounds_min + object.bounds_max);
}

DistanceMaps::DistanceMaps(const GpuScene& scene, std::vector<DistanceMapObject> objects,
                           int resolution)
    : objects_(std::move(objects)), resolution_(resolution) {
  if (objects_.empty() || objects_.size() > std::size_t(gpu::kMaxDistanceMapObjects))
    throw std::logic_error(fmt::format("{} distance-map objects (1 to {})", objects_.size(),
                                       gpu::kMaxDistanceMapObjects));
  const float extent = glm::length(scene.boundsMax() - scene.boundsMin());
  near_ = 1e-4f * extent;
  far_ = 2.0f * extent;
  const int cubes = int(objects_.size());
  views_.emplace(6 * resolution_, cubes * resolution_);
  light_.emplace(6 * resolution_, cubes * resolution_);
  for (gl::Texture& maps : maps_) {
    maps = gl::Texture::makeCubeArray(GL_RGBA32F, resolution_, cubes);
    // Bilinear within a face: the search compares a point's distance with the surface's between
    // texel centres, as the book's texCUBElod does.
    maps.setFilter(GL_LINEAR, GL_LINEAR);
    maps.setWrap(GL_CLAMP_TO_EDGE);
  }
  block_ = gl::Buffer(sizeof(gpu::DistanceMapBlock), nullptr);
  writeBlock();
  compose_ = gl::buildProgram({{GL_COMPUTE_SHADER, "realtime/distance_map/compose.comp.glsl"}});
  downsample_ =
      gl::buildProgram({{GL_COMPUTE_SHADER, "realtime/distance_map/downsample.comp.glsl"}});
}

void DistanceMaps::rasterise(const GpuScene& scene) {
  std::vector<GBufferView> views;
  for (std::size_t k = 0; k < objects_.size(); ++k)
    for (int face = 0; face < 6; ++face) {
      const DistanceMapObject& object = objects_[k];
      views.push_back({cubeFaceViewProjection(object.reference_point, face, near_, far_),
                       object.reference_point, face * resolution_, int(k) * resolution_,
                       resolution_, resolution_, object.first_triangle, object.end_triangle});
    }
  views_->renderViews(scene, views);
}

void DistanceMaps::clearLight() const {
  light_->clear(0, 0, 0);
}

void DistanceMaps::writeBlock() {
  gpu::DistanceMapBlock block{};
  for (std::size_t k = 0; k < objects_.size(); ++k)
    block.objects[k] = {glm::vec4(objects_[k].reference_point, 1.0f),
                        glm::ivec4(objects_[k].first_triangle, objects_[k].end_triangle, 0, 0)};
  block.counts = glm::ivec4(int(objects_.size()), resolution_, 0, 0);
  block.search =
      glm::ivec4(search_.method, search_.linear_steps, search_.secant_steps, search_.fresnel);
  block_.update(0, sizeof(block), &block);
}

void DistanceMaps::bind() const {
  maps().bind(gpu::kDistanceMapUnit);
  block_.bindBase(GL_UNIFORM_BUFFER, gpu::kDistanceMapObjectsBinding);
}

void DistanceMaps::compose(const GpuScene& scene, int rounds) {
  // The first round reads black maps: a specular object another map sees shows nothing yet.
  const float black[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearTexImage(maps_[current_].id(), 0, GL_RGBA, GL_FLOAT, black);
  compose_.use();
  scene.bindSceneBuffers();
  views_->bindTextures();
  light_->color().bind(gpu::kDistanceMapLightUnit);
  views_->albedo().bind(gpu::kDistanceMapCodeUnit);
  compose_.set("u_sky_radiance", scene.scene().sky_radiance);
  for (int round = 0; round < rounds; ++round) {
    bind();
    glBindImageTexture(gpu::kImageDestinationUnit, maps_[1 - current_].id(), 0, GL_TRUE, 0,
                       GL_WRITE_ONLY, GL_RGBA32F);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT |
                    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    gl::dispatchCompute(groups(6 * resolution_), groups(int(objects_.size()) * resolution_), 1);
    current_ = 1 - current_;
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void DistanceMaps::downsample(const gl::Texture& destination) const {
  const int size = destination.width();
  if (size < 1 || resolution_ % size != 0 || destination.depth() != maps().depth())
    throw std::logic_error(fmt::format("a {}² map cannot be averaged into {}² faces of {} layers",
                                       resolution_, size, destination.depth()));
  downsample_.use();
  downsample_.set("u_block", resolution_ / size);
  downsample_.set("u_size", size);
  glBindImageTexture(gpu::kImageSourceUnit, maps().id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
  glBindImageTexture(gpu::kImageDestinationUnit, destination.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                     GL_RGBA32F);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  gl::dispatchCompute(groups(size), groups(size), GLuint(destination.depth()));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace gib::rt
