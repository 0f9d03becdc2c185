#include "realtime/render_target.h"

namespace gib::rt {

RenderTarget::RenderTarget(int width, int height)
    : width_(width),
      height_(height),
      color_(gl::Texture::make2D(GL_RGBA32F, width, height)),
      depth_(gl::Texture::make2D(GL_DEPTH_COMPONENT32F, width, height)) {
  framebuffer_.attachColor(0, color_);
  framebuffer_.attachDepth(depth_);
  framebuffer_.setDrawBuffers(1);
  framebuffer_.checkComplete();
}

void RenderTarget::bind() const {
  framebuffer_.bind();
  glViewport(0, 0, width_, height_);
}

void RenderTarget::clear(float r, float g, float b) const {
  const float color[4] = {r, g, b, 1.0f};
  const float depth = 1.0f;
  // Clears obey the write masks: a pass that left them off must not keep the target from clearing.
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, color);
  glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &depth);
}

image::Image RenderTarget::read() const {
  return gl::readPixels(framebuffer_, 0, width_, height_, 3);
}

}  // namespace gib::rt
