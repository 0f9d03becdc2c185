#include "realtime/gbuffer/gbuffer.h"

#include "realtime/gbuffer/gbuffer_views_shared.h"
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/gl/shader_library.h"

#include <fmt/format.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>

namespace gib::rt {

namespace {

constexpr int kTargets = 3;  // position, normal, albedo
// What a pixel no triangle covers holds: distance and material −1.
constexpr float kBackground[4] = {0.0f, 0.0f, 0.0f, -1.0f};
constexpr float kNoAlbedo[4] = {0.0f, 0.0f, 0.0f, 0.0f};

// The nearest surface wins; both sides of a triangle reflect, so no culling.
gl::PipelineState drawState(int width, int height) {
  return {.depth_test = GL_LESS, .viewport = gl::PixelRect{0, 0, width, height}};
}

}  // namespace

GBuffer::GBuffer(int width, int height)
    : width_(width),
      height_(height),
      position_(gl::Texture::make2D(GL_RGBA32F, width, height)),
      normal_(gl::Texture::make2D(GL_RGBA32F, width, height)),
      albedo_(gl::Texture::make2D(GL_RGBA32F, width, height)),
      depth_(gl::Texture::make2D(GL_DEPTH_COMPONENT32F, width, height)),
      program_(gl::buildProgram({{GL_VERTEX_SHADER, "realtime/gbuffer/gbuffer.vert.glsl"},
                                 {GL_FRAGMENT_SHADER, "realtime/gbuffer/gbuffer.frag.glsl"}})) {
  // A deferred pass reads texels, never filtered values: blending a surface with the background
  // or with another surface would be a position or normal that nothing has.
  for (gl::Texture* texture : {&position_, &normal_, &albedo_})
    texture->setFilter(GL_NEAREST, GL_NEAREST);
  framebuffer_.attachColor(0, position_);
  framebuffer_.attachColor(1, normal_);
  framebuffer_.attachColor(2, albedo_);
  framebuffer_.attachDepth(depth_);
  framebuffer_.setDrawBuffers(kTargets);
  framebuffer_.checkComplete();
}

void GBuffer::render(const GpuScene& scene, gl::PassProfiler* profiler) {
  // The scene's camera is set up for its own image; a G-buffer of another shape would stretch it.
  if (std::int64_t(width_) * scene.height() != std::int64_t(height_) * scene.width())
    throw std::logic_error(fmt::format("a {}×{} G-buffer cannot hold a view of a {}×{} camera",
                                       width_, height_, scene.width(), scene.height()));
  std::optional<gl::PassProfiler::Scope> scope;
  if (profiler) scope.emplace(profiler->pass(kGBufferPass));

  const gl::PipelineScope state(drawState(width_, height_));
  bindAndClear();
  program_.use();
  scene.bindSceneBuffers();
  scene.draw();
}

void GBuffer::renderViews(const GpuScene& scene, const std::vector<GBufferView>& views) {
  if (!views_program_.id())
    views_program_ = gl::buildLayeredProgram(
        {"realtime/gbuffer/gbuffer.vert.glsl", "realtime/gbuffer/gbuffer_views.geom.glsl",
         "realtime/gbuffer/gbuffer.frag.glsl"},
        "#define EXPLICIT_VIEW 1\n", views_from_geometry_shader_, gl::InstanceTarget::kViewport);
  // Views go in draws of up to kMaxGBufferViewsPerDraw, each draw's block of records at an
  // offset a uniform block may start at; all of them, and every draw's records, are written at
  // once rather than between draws.
  const std::size_t block_bytes = sizeof(gpu::GBufferViewRecord) * gpu::kMaxGBufferViewsPerDraw;
  const std::size_t stride = views_.alignedSize(block_bytes);
  const std::size_t draws =
      (views.size() + gpu::kMaxGBufferViewsPerDraw - 1) / gpu::kMaxGBufferViewsPerDraw;
  std::vector<std::byte> blocks(draws * stride);
  std::vector<DrawArraysIndirectCommand> records;
  std::vector<std::size_t> first_record(draws + 1, 0);
  for (std::size_t d = 0; d < draws; ++d) {
    for (std::size_t i = 0; i < std::size_t(gpu::kMaxGBufferViewsPerDraw); ++i) {
      const std::size_t v = d * gpu::kMaxGBufferViewsPerDraw + i;
      if (v >= views.size()) break;
      const gpu::GBufferViewRecord record{
          views[v].view_projection, glm::vec4(views[v].eye, 1.0f),
          glm::ivec4(views[v].excluded_first, views[v].excluded_end, 0, 0)};
      std::memcpy(blocks.data() + d * stride + i * sizeof(record), &record, sizeof(record));
      scene.appendViewRecords(views[v].view_projection, GLuint(i), cull_views_, records);
    }
    first_record[d + 1] = records.size();
  }
  views_.beginRound({blocks.size(), records.size() * sizeof(DrawArraysIndirectCommand)});
  const std::size_t blocks_offset = views_.push(blocks);
  const std::size_t records_offset = views_.push(records);

  // The scope's end sets every viewport of the array back to the one it found.
  const gl::PipelineScope state(drawState(width_, height_));
  bindAndClear();
  views_program_.use();
  scene.bindSceneBuffers();
  for (std::size_t d = 0; d < draws; ++d) {
    for (std::size_t i = 0; i < std::size_t(gpu::kMaxGBufferViewsPerDraw); ++i) {
      const std::size_t v = d * gpu::kMaxGBufferViewsPerDraw + i;
      if (v >= views.size()) break;
      glViewportIndexedf(GLuint(i), float(views[v].x), float(views[v].y), float(views[v].width),
                         float(views[v].height));
    }
    views_.bindRange(GL_UNIFORM_BUFFER, gpu::kGBufferViewsBinding, blocks_offset + d * stride,
                     block_bytes);
    scene.drawRecords(views_.id(),
                      records_offset + first_record[d] * sizeof(DrawArraysIndirectCommand),
                      first_record[d + 1] - first_record[d]);
  }
}

// Binds and clears the buffer; the caller's scope holds the state it is drawn with (drawState),
// whose write masks let the clears clear every channel and the depth.
void GBuffer::bindAndClear() const {
  framebuffer_.bind();
  const float far_depth = 1.0f;
  glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, kBackground);
  glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 1, kBackground);
  glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 2, kNoAlbedo);
  glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &far_depth);
}

void GBuffer::bindTextures() const {
  position_.bind(gpu::kGBufferPositionUnit);
  normal_.bind(gpu::kGBufferNormalUnit);
}

}  // namespace gib::rt
