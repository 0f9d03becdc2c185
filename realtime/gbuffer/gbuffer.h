// A geometry buffer of the camera view: what each pixel's primary ray hits. Deferred techniques
// shade from it, and the pixel-agreement test compares it with Embree's primary rays.
#pragma once

#include "realtime/gl/objects.h"
#include "realtime/gl/stream_buffer.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/render_target.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <string_view>
#include <vector>

namespace gib::rt {

namespace gl {
class PassProfiler;
}

// A view other than the scene camera's, drawn into a rectangle of the G-buffer (the tiles of
// the irradiance volume's cube maps). Positions' w is the distance from `eye`, and normals are
// turned to face it (a probe's view has no emission to keep one-sided).
struct GBufferView {
  glm::mat4 view_projection{1.0f};
  glm::vec3 eye{0.0f};
  int x = 0, y = 0, width = 0, height = 0;  // viewport in texels
  // Triangles [first, end) of the scene's list (GpuScene's order: meshes in order) left out of
  // this view: a distance map does not see the object it belongs to.
  int excluded_first = 0, excluded_end = 0;
};

// The pass GBuffer::render opens when given a profiler.
inline constexpr std::string_view kGBufferPass = "g-buffer";

class GBuffer {
 public:
  GBuffer(int width, int height);

  // Rasterises the scene from its camera.
  void render(const GpuScene& scene, gl::PassProfiler* profiler = nullptr);
  // Clears the whole buffer and rasterises each view into its rectangle: multi-draws of up to
  // gpu::kMaxGBufferViewsPerDraw views, view i into viewport i of the viewport array, each view
  // drawing only the triangle chunks its frustum may touch (view_culling.h).
  void renderViews(const GpuScene& scene, const std::vector<GBufferView>& views);

  // RGBA32F textures; background pixels have distance (w of position) and material = −1.
  const gl::Texture& position() const { return position_; }  // world position, w: ray distance
  // Unit shading normal (the geometric one on a flat mesh, shading_normal.glsl), w: material.
  const gl::Texture& normal() const { return normal_; }
  // Material diffuse RGB; w: ±(t + 1) for the scene triangle t seen (GpuScene's list), + where
  // the eye is on its front side: a distance map's texels tell their object and an emitter's
  // side by it (a probe view's normal is turned to its eye), the specular pass its pixel's
  // object. Background: 0.
  const gl::Texture& albedo() const { return albedo_; }
  // Binds position and normal, what deferred passes read (gbuffer_maps.glsl), to their units of
  // gl/binding_plan_shared.h.
  void bindTextures() const;

  int width() const { return width_; }
  int height() const { return height_; }

  // renderViews selects each view's viewport in the geometry shader even where the vertex shader
  // could (tests compare the two paths).
  void selectViewportsInGeometryShader() {
    views_from_geometry_shader_ = true;
    views_program_ = gl::Program();
  }
  // renderViews draws every triangle into every view (tests compare culling with drawing all).
  void drawViewsWithoutCulling() { cull_views_ = false; }

 private:
  int width_, height_;
  gl::Texture position_, normal_, albedo_, depth_;
  void bindAndClear() const;

  gl::Framebuffer framebuffer_;
  gl::Program program_;
  gl::Program views_program_;  // built on first use of renderViews
  // Per renderViews call, a round of their own: every view (gpu::GBufferViewRecord), each
  // draw's block at an offset a uniform block may start at, and the draws' records.
  gl::StreamBuffer views_;
  bool cull_views_ = true;
  bool views_from_geometry_shader_ = false;
};

}  // namespace gib::rt
