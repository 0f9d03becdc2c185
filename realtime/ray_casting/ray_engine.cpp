#include "realtime/ray_casting/ray_engine.h"

#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/gl/shader_library.h"
#include "realtime/ray_casting/ray_engine_shared.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <stdexcept>

namespace gib::rt {

namespace {

// Each triangle's bounding sphere (centre: its bounding box's centre; radius: the farthest
// vertex), in list order, the set's coordinates.
std::vector<glm::vec4> triangleSpheres(const IvmTriangleSet& set) {
  std::vector<glm::vec4> spheres;
  spheres.reserve(set.size());
  for (const IvmTriangle& t : set.triangles) {
    const glm::vec3 centre =
        0.5f * (glm::min(t.a, glm::min(t.b, t.c)) + glm::max(t.a, glm::max(t.b, t.c)));
    const float radius =
        std::max({glm::length(t.a - centre), glm::length(t.b - centre), glm::length(t.c - centre)});
    // Rounding must not shrink the sphere below its vertices.
    spheres.emplace_back(centre, radius * (1.0f + 1e-5f) + 1e-6f);
  }
  return spheres;
}

}  // namespace

RayEngine::RayEngine(const IvmTriangleSet& set, bool cones, int tile_size)
    : cones_(cones),
      tile_size_(tile_size),
      depth_scale_(std::max(1e-6f, glm::length(set.bounds_max - set.bounds_min))),
      triangle_count_(set.size()),
      triangles_(set) {
  GLfloat point_range[2] = {0, 0};
  glGetFloatv(GL_POINT_SIZE_RANGE, point_range);
  if (cones_ && (tile_size_ < 1 || float(tile_size_) > point_range[1]))
    throw std::runtime_error(fmt::format(
        "the ray engine's tile of {} pixels is larger than the GL driver's largest point ({})",
        tile_size_, point_range[1]));
  if (cones_) {
    spheres_cpu_ = triangleSpheres(set);
    spheres_buffer_ = gl::Buffer::fromVector(spheres_cpu_, 0);
    spheres_ = gl::Texture::makeBuffer(GL_RGBA32F, spheres_buffer_);
    cone_program_ =
        gl::buildProgram({{GL_COMPUTE_SHADER, "realtime/ray_casting/ray_cones.comp.glsl"}});
  }
  draw_program_ = gl::buildProgram(
      {{GL_VERTEX_SHADER, cones_ ? "realtime/ray_casting/ray_engine_tiles.vert.glsl"
                                 : "realtime/ray_casting/ray_engine.vert.glsl"},
       {GL_FRAGMENT_SHADER, "realtime/ray_casting/ray_engine.frag.glsl"}});
}

void RayEngine::setRays(const std::vector<CastRay>& rays, int width) {
  count_ = rays.size();
  width_ = std::max(1, std::min(width, int(std::max<std::size_t>(1, rays.size()))));
  height_ = std::max(1, int((rays.size() + std::size_t(width_) - 1) / std::size_t(width_)));
  // With cones the target is whole tiles: a point primitive whose centre fell outside the
  // viewport would be clipped, and the rays of a partial tile at the edge never tested.
  const int step = cones_ ? tile_size_ : 1;
  target_width_ = (width_ + step - 1) / step * step;
  target_height_ = (height_ + step - 1) / step * step;
  // Pixels past the last ray, or past the rays' width, get an empty segment (t_max < t_min).
  std::vector<glm::vec4> origins(std::size_t(target_width_) * target_height_,
                                 glm::vec4(0, 0, 0, 1)),
      directions(origins.size(), glm::vec4(0, 0, 1, 0));
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const std::size_t texel = (i / width_) * target_width_ + i % width_;
    origins[texel] = glm::vec4(rays[i].origin, rays[i].t_min);
    directions[texel] = glm::vec4(rays[i].direction, rays[i].t_max);
  }
  origins_ = gl::Texture::make2D(GL_RGBA32F, target_width_, target_height_);
  directions_ = gl::Texture::make2D(GL_RGBA32F, target_width_, target_height_);
  glTextureSubImage2D(origins_.id(), 0, 0, 0, target_width_, target_height_, GL_RGBA, GL_FLOAT,
                      origins.data());
  glTextureSubImage2D(directions_.id(), 0, 0, 0, target_width_, target_height_, GL_RGBA, GL_FLOAT,
                      directions.data());
  target_ = std::make_unique<RenderTarget>(target_width_, target_height_);
  if (cones_) {
    tiles_x_ = target_width_ / tile_size_;
    tiles_y_ = target_height_ / tile_size_;
    cones_buffer_ =
        gl::Buffer(std::size_t(tiles_x_) * tiles_y_ * 2 * sizeof(glm::vec4), nullptr, 0);
    cones_texture_ = gl::Texture::makeBuffer(GL_RGBA32F, cones_buffer_);
  }
}

void RayEngine::cast() {
  if (count_ == 0) return;
  origins_.bind(GLuint(gpu::kRayEngineOriginsUnit));
  directions_.bind(GLuint(gpu::kRayEngineDirectionsUnit));
  triangles_.bind();
  const int tiles = tiles_x_ * tiles_y_;
  if (cones_) {
    cone_program_.use();
    cone_program_.set("u_tiles_x", tiles_x_);
    cone_program_.set("u_tile_count", tiles);
    cone_program_.set("u_tile_size", tile_size_);
    cone_program_.set("u_ray_count", int(count_));
    cone_program_.set("u_width", width_);
    cones_buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, GLuint(gpu::kRayEngineConesBinding));
    gl::dispatchCompute(
        GLuint((tiles + gpu::kRayEngineConeGroupSize - 1) / gpu::kRayEngineConeGroupSize), 1, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    cones_texture_.bind(GLuint(gpu::kRayEngineConesUnit));
    spheres_.bind(GLuint(gpu::kRayEngineSpheresUnit));
  }
  target_->bind();
  target_->clear(0.0f, 0.0f, 0.0f);  // y = 0: no triangle (ray_engine.frag.glsl)
  gl::PipelineState state;
  state.depth_test = GL_LESS;
  state.program_point_size = cones_;
  gl::PipelineScope scope(state);
  draw_program_.use();
  draw_program_.set("u_ray_count", int(count_));
  draw_program_.set("u_width", width_);
  draw_program_.set("u_depth_scale", depth_scale_);
  empty_vertices_.bind();
  if (cones_) {
    draw_program_.set("u_tiles_x", tiles_x_);
    draw_program_.set("u_tile_size", tile_size_);
    draw_program_.set("u_target_size", glm::ivec2(target_width_, target_height_));
    gl::drawArraysInstanced(GL_POINTS, 0, GLsizei(triangle_count_), GLsizei(tiles));
  } else {
    gl::drawArraysInstanced(GL_TRIANGLES, 0, 3, GLsizei(triangle_count_));
  }
}

std::vector<gpu::RayCastHit> RayEngine::hits() const {
  std::vector<gpu::RayCastHit> hits(count_, noRayHit());
  if (count_ == 0) return hits;
  std::vector<glm::vec4> texels(std::size_t(target_width_) * target_height_);
  glGetTextureImage(target_->color().id(), 0, GL_RGBA, GL_FLOAT,
                    GLsizei(texels.size() * sizeof(glm::vec4)), texels.data());
  for (std::size_t i = 0; i < count_; ++i) {
    const glm::vec4& h = texels[(i / width_) * target_width_ + i % width_];
    if (h.y < 0.5f) continue;
    hits[i] = {h.x, std::uint32_t(h.y) - 1u, h.z, h.w};
  }
  return hits;
}

std::vector<glm::vec4> RayEngine::readCones() const {
  if (!cones_ || count_ == 0) return {};
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  return gl::readBuffer<glm::vec4>(cones_buffer_, 2 * std::size_t(tiles_x_) * tiles_y_);
}

double RayEngine::keptPairFraction() const {
  if (!cones_ || count_ == 0) return 1.0;
  const std::size_t tiles = std::size_t(tiles_x_) * tiles_y_;
  const std::vector<glm::vec4> cones = readCones();
  std::size_t kept = 0;
  for (std::size_t t = 0; t < tiles; ++t)
    for (const glm::vec4& sphere : spheres_cpu_)
      kept += gpu::sphereMeetsCone(sphere, cones[2 * t], cones[2 * t + 1]) ? 1 : 0;
  return double(kept) / double(tiles * spheres_cpu_.size());
}

std::size_t RayEngine::bytes() const {
  const std::size_t pixels = std::size_t(target_width_) * target_height_;
  // Rays (2 × RGBA32F), the target (RGBA32F colour, 32-bit depth), cones and spheres.
  return triangles_.bytes() + spheres_buffer_.bytes() + cones_buffer_.bytes() +
         pixels * (2 * 16 + 16 + 4);
}

}  // namespace gib::rt
