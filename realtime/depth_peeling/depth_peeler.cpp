#include "realtime/depth_peeling/depth_peeler.h"

#include "common/input_error.h"
#include "realtime/depth_peeling/depth_peeling_shared.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/gl/shader_library.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace gib::rt {

DepthPeeler::DepthPeeler(int resolution, int max_layers, glm::vec3 centre, float radius)
    : resolution_(resolution),
      max_layers_(max_layers),
      centre_(centre),
      radius_(std::max(radius, 1e-6f)) {
  if (resolution < 2 || max_layers < 1)
    throw InputError(fmt::format(
        "depth peeling needs at least 2 pixels per side and 1 layer (got {} and {}); raise "
        "peel_resolution or max_layers",
        resolution, max_layers));
  // R pixels span 2r + s: a shift of the grid by up to a pixel still covers the sphere.
  pixel_size_ = 2.0f * radius_ / float(resolution - 1);
  epsilon_ = kPeelEpsilonFraction * 2.0f * radius_;
  layers_ = gl::Texture::make2DArray(GL_RGBA32F, resolution, resolution, max_layers);
  layers_.setFilter(GL_NEAREST, GL_NEAREST);
  for (gl::Texture& depth : depth_) {
    depth = gl::Texture::make2D(GL_R32F, resolution, resolution);
    depth.setFilter(GL_NEAREST, GL_NEAREST);
  }
  depth_buffer_ = gl::Texture::make2D(GL_DEPTH_COMPONENT32F, resolution, resolution);
  framebuffer_.attachDepth(depth_buffer_);
  any_samples_ = gl::Query(GL_ANY_SAMPLES_PASSED);
  program_ =
      gl::buildProgram({{GL_VERTEX_SHADER, "realtime/depth_peeling/depth_peel.vert.glsl"},
                        {GL_FRAGMENT_SHADER, "realtime/depth_peeling/depth_peel.frag.glsl"}});
}

PeelProjection DepthPeeler::projection(const PeelBundle& bundle) const {
  const glm::vec3 d = glm::normalize(bundle.direction);
  glm::vec3 right = glm::cross(d, bundle.up);
  if (!(glm::dot(right, right) > 1e-8f))  // up along the direction: any perpendicular will do
    right = glm::cross(d, std::abs(d.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0));
  const glm::vec3 t = glm::normalize(right);
  const glm::vec3 b = glm::cross(t, d);
  const float width = float(resolution_) * pixel_size_;  // of the window, in scene units
  // Window coordinates relative to the centre: x in [x_min, x_min + width].
  const glm::vec2 low = glm::vec2(-radius_) - bundle.offset * pixel_size_;
  PeelProjection p;
  p.direction = d;
  p.plane_origin = centre_ - radius_ * d;
  glm::mat4 m(0.0f);  // m[column][row]
  const auto row = [&](int r, glm::vec3 axis, float scale, float shift) {
    for (int c = 0; c < 3; ++c) m[c][r] = scale * axis[c];
    m[3][r] = shift;
  };
  const float s = 2.0f / width;
  row(0, t, s, -s * (glm::dot(t, centre_) + low.x) - 1.0f);
  row(1, b, s, -s * (glm::dot(b, centre_) + low.y) - 1.0f);
  // Depth d·(p − plane origin) in [0, 2r] to clip z in [−1, 1].
  row(2, d, 1.0f / radius_, -glm::dot(d, p.plane_origin) / radius_ - 1.0f);
  m[3][3] = 1.0f;
  p.clip_from_world = m;
  return p;
}

int DepthPeeler::peel(const atlas::AtlasMesh& mesh, const PeelBundle& bundle) {
  const PeelProjection p = projection(bundle);
  const float empty[4] = {0, 0, 0, 0};
  glClearTexImage(layers_.id(), 0, GL_RGBA, GL_FLOAT, empty);
  program_.use();
  program_.set("u_clip_from_world", p.clip_from_world);
  program_.set("u_plane_origin", p.plane_origin);
  program_.set("u_direction", p.direction);
  program_.set("u_epsilon", epsilon_);
  // Both sides of every triangle: a global ray crosses a surface whichever way it faces.
  const gl::PipelineScope state(
      {.depth_test = GL_LESS, .viewport = gl::PixelRect{0, 0, resolution_, resolution_}});
  const float beyond[4] = {gpu::kPeelBeyondEverything, 0, 0, 0};
  layer_count_ = 0;
  for (int k = 0; k < max_layers_; ++k) {
    gl::Texture& kept = depth_[std::size_t(k % 2)];
    framebuffer_.attachColor(0, layers_, 0, k);
    framebuffer_.attachColor(1, kept);
    framebuffer_.setDrawBuffers(2);
    framebuffer_.bind();
    glClearBufferfv(GL_COLOR, 1, beyond);
    glClear(GL_DEPTH_BUFFER_BIT);
    program_.set("u_first", k == 0 ? 1 : 0);
    depth_[std::size_t((k + 1) % 2)].bind(gpu::kPeelPreviousDepthUnit);
    glBeginQuery(GL_ANY_SAMPLES_PASSED, any_samples_.id());
    mesh.draw();
    glEndQuery(GL_ANY_SAMPLES_PASSED);
    if (any_samples_.result() == 0) break;  // every ray has left the scene
    layer_count_ = k + 1;
  }
  return layer_count_;
}

std::vector<glm::vec4> DepthPeeler::layerTexels(int layer) const {
  const std::size_t n = std::size_t(resolution_) * std::size_t(resolution_);
  std::vector<glm::vec4> texels(n);
  glGetTextureSubImage(layers_.id(), 0, 0, 0, layer, resolution_, resolution_, 1, GL_RGBA, GL_FLOAT,
                       GLsizei(n * sizeof(glm::vec4)), texels.data());
  return texels;
}

std::vector<int> DepthPeeler::surfacesPerPixel() const {
  std::vector<int> count(std::size_t(resolution_) * std::size_t(resolution_), 0);
  for (int k = 0; k < layer_count_; ++k) {
    const std::vector<glm::vec4> texels = layerTexels(k);
    for (std::size_t i = 0; i < texels.size(); ++i)
      if (texels[i].z != gpu::kPeelEmpty) ++count[i];
  }
  return count;
}

image::Image DepthPeeler::layerDepthImage(int layer) const {
  image::Image picture(resolution_, resolution_);
  const std::vector<glm::vec4> texels = layerTexels(layer);
  const float range = 2.0f * radius_;
  for (int y = 0; y < resolution_; ++y)
    for (int x = 0; x < resolution_; ++x) {
      const glm::vec4& t = texels[std::size_t(y * resolution_ + x)];
      const float shade = t.z == gpu::kPeelEmpty ? 0.0f : 1.0f - 0.8f * t.w / range;
      float* out = picture.pixel(x, resolution_ - 1 - y);  // the image's top row first
      out[0] = out[1] = out[2] = shade;
    }
  return picture;
}

}  // namespace gib::rt
