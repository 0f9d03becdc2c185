#include "realtime/gbuffer/gbuffer.h"

#include "realtime/gbuffer/gbuffer_views_shared.h"
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/shader_library.h"

#include <fmt/format.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <stdexcept>

namespace gib::rt {

namespace {

constexpr int kTargets = 3;  // position, normal, albedo
// What a pixel no triangle covers holds: distance and material −1.
constexpr float kBackground[4] = {0.0f, 0.0f, 0.0f, -1.0f};
constexpr float kNoAlbedo[4] = {0.0f, 0.0f, 0.0f, 0.0f};

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

  clearAndSetState();
  program_.use();
  scene.bindSceneBuffers();
  scene.draw();
}

void GBuffer::renderViews(const GpuScene& scene, const std::vector<GBufferView>& views) {
  if (!views_program_.id()) {
    views_program_ = gl::buildLayeredProgram(
        {"realtime/gbuffer/gbuffer.vert.glsl", "realtime/gbuffer/gbuffer_views.geom.glsl",
         "realtime/gbuffer/gbuffer.frag.glsl"},
        "#define EXPLICIT_VIEW 1\n", views_from_geometry_shader_, gl::InstanceTarget::kViewport);
    views_ = gl::Buffer(sizeof(gpu::GBufferViewRecord) * gpu::kMaxGBufferViewsPerDraw, nullptr);
  }
  clearAndSetState();
  views_program_.use();
  scene.bindSceneBuffers();
  // One instanced draw per block of views, view i of a block in viewport i.
  std::vector<gpu::GBufferViewRecord> records;
  for (std::size_t first = 0; first < views.size(); first += gpu::kMaxGBufferViewsPerDraw) {
    const std::size_t count =
        std::min(views.size() - first, std::size_t(gpu::kMaxGBufferViewsPerDraw));
    records.clear();
    for (std::size_t i = first; i < first + count; ++i) {
      const GBufferView& v = views[i];
      records.push_back({v.view_projection, glm::vec4(v.eye, 1.0f)});
      glViewportIndexedf(GLuint(i - first), float(v.x), float(v.y), float(v.width),
                         float(v.height));
    }
    views_.update(0, records.size() * sizeof(gpu::GBufferViewRecord), records.data());
    views_.bindBase(GL_UNIFORM_BUFFER, gpu::kGBufferViewsBinding);
    scene.draw(int(count));
  }
  glViewport(0, 0, width_, height_);  // every viewport of the array back to the whole buffer
}

void GBuffer::clearAndSetState() const {
  framebuffer_.bind();
  glViewport(0, 0, width_, height_);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  const float far_depth = 1.0f;
  glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, kBackground);
  glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 1, kBackground);
  glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 2, kNoAlbedo);
  glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &far_depth);
  // Each pass sets the state it relies on. Both sides of a triangle reflect, so no culling.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
}

void GBuffer::bindTextures() const {
  position_.bind(gpu::kGBufferPositionUnit);
  normal_.bind(gpu::kGBufferNormalUnit);
}

}  // namespace gib::rt
