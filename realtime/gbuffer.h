// A geometry buffer of the camera view: what each pixel's primary ray hits. Deferred techniques
// shade from it, and the pixel-agreement test compares it with Embree's primary rays.
#pragma once

#include "realtime/gl/objects.h"
#include "realtime/gpu_scene.h"
#include "realtime/render_target.h"

namespace gib::rt {

namespace gl {
class PassProfiler;
}

class GBuffer {
 public:
  GBuffer(int width, int height);

  // Rasterises the scene from its camera.
  void render(const GpuScene& scene, gl::PassProfiler* profiler = nullptr);

  // RGBA32F textures; background pixels have distance (w of position) and material = −1.
  const gl::Texture& position() const { return position_; }  // world position, w: ray distance
  const gl::Texture& normal() const { return normal_; }      // unit geometric normal, w: material
  const gl::Texture& albedo() const { return albedo_; }      // material diffuse RGB, w: 1
  // Binds position, normal, albedo to texture units first, first+1, first+2.
  void bindTextures(GLuint first) const;

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_, height_;
  gl::Texture position_, normal_, albedo_, depth_;
  gl::Framebuffer framebuffer_;
  gl::Program program_;
};

}  // namespace gib::rt
