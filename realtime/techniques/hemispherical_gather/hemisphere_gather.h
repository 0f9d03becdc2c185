// Irradiance at a grid of the camera image's pixels, gathered by rasterizing the scene around
// each of them (Fournier & Péroche §5.2): a 160° perspective or a fish-eye view per point, the
// scene's atlas mesh textured with a radiance atlas, a layer per point and one instanced draw per
// batch; a compute pass sums each view with its pixels' cos θ dω. The technique gathers the
// directly lit scene; tests gather a radiance they set.
#pragma once

#include "realtime/atlas/atlas_mesh.h"
#include "realtime/gbuffer/gbuffer.h"
#include "realtime/gl/objects.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gpu_scene/gpu_scene.h"

#include <glm/vec2.hpp>

#include <optional>
#include <string_view>

namespace gib::rt {

// The passes HemisphereGather::gather opens (inside its caller's).
inline constexpr std::string_view kGatherPass = "gather";
inline constexpr std::string_view kGatherViewsPass = "gather views";
inline constexpr std::string_view kGatherSumPass = "gather sum";
inline constexpr std::string_view kGatherSlicesPass = "gather slices";

class VoxelSlices;

class HemisphereGather {
 public:
  // `projection` is gpu::kProjection*; views are view_size² pixels; one point per spacing ×
  // spacing block of a width × height image; `extent` the scene's (near plane, lift).
  HemisphereGather(int projection, int view_size, int spacing, int width, int height, float extent);

  // Gathers at every grid point of `gbuffer` the radiance `radiance_atlas` gives the mesh's
  // surfaces; the views are cleared to `background` where nothing is drawn. The voxel-slice
  // projection draws the mesh near each point only, and `slices` beyond it.
  void gather(const GpuScene& scene, const atlas::AtlasMesh& mesh,
              const gl::Texture& radiance_atlas, const GBuffer& gbuffer, gl::PassProfiler& profiler,
              const glm::vec3& background = glm::vec3(0.0f), const VoxelSlices* slices = nullptr);

  // RGBA32F, grid().x × grid().y: irradiance at each point (w 1 where a point was gathered).
  const gl::Texture& irradiance() const { return irradiance_; }
  glm::ivec2 grid() const { return grid_; }
  int spacing() const { return spacing_; }
  int pointsPerBatch() const { return batch_; }
  // The uniforms gather_point.glsl reads, for another program that finds the points.
  void setPointUniforms(const gl::Program& program) const;

 private:
  int projection_, view_size_, spacing_;
  float extent_;
  glm::ivec2 grid_{0};
  int batch_ = 0;
  std::optional<gl::LayeredTarget> views_;  // RGBA32F, a layer per point of a batch
  gl::Texture irradiance_;
  gl::Program view_program_, sum_program_, slices_program_;
  gl::VertexArray empty_vertex_array_;
};

}  // namespace gib::rt
