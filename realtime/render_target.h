// The image a technique renders: linear float RGBA with a depth buffer, read back as the common
// image type (pixel (0,0) top left) for metrics and EXR output.
#pragma once

#include "image/image.h"
#include "realtime/gl/objects.h"

namespace gib::rt {

class RenderTarget {
 public:
  RenderTarget(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  const gl::Texture& color() const { return color_; }  // GL_RGBA32F
  const gl::Texture& depth() const { return depth_; }  // GL_DEPTH_COMPONENT32F
  const gl::Framebuffer& framebuffer() const { return framebuffer_; }

  // Binds the framebuffer and sets the viewport to the whole target.
  void bind() const;
  // Clears colour to `rgb` (alpha 1) and depth to 1.
  void clear(float r, float g, float b) const;
  // The RGB channels, pixel (0,0) at the top left.
  image::Image read() const;

 private:
  int width_, height_;
  gl::Texture color_, depth_;
  gl::Framebuffer framebuffer_;
};

}  // namespace gib::rt
