// `jittered_light_sampling`: direct illumination from area lights sampled by the rasterizer
// (Fournier & Péroche §4). Every camera G-buffer pixel is a point; for each area light, batches
// of points render the light and its occluders into small coverage images (one layer per point,
// one instanced draw per batch), by an occlusion-query-like count, regular pixel centres or
// jittered samples; a compute pass weighs each point's visible samples by their solid angle, the
// BRDF and the receiver's cosine. Spot, directional and sky lights are shadow-mapped as `direct`
// does. See README.md beside this file.
#pragma once

#include "realtime/gbuffer/gbuffer.h"
#include "realtime/lighting/surface_lighting.h"
#include "realtime/technique.h"
#include "realtime/techniques/jittered_light_sampling/area_lights.h"
#include "realtime/techniques/jittered_light_sampling/light_coverage_sampler.h"

#include <optional>

namespace gib::rt {

class JitteredLightSamplingTechnique final : public Technique {
 public:
  explicit JitteredLightSamplingTechnique(const ParameterValues& parameters);

  void prepare(const GpuScene& scene, int width, int height) override;
  void render(Frame& frame) override;
  scene::PathClass pathClass() const override { return {0, 1}; }
  std::vector<TechniqueStatistic> statistics() const override;

 private:
  void sampleAreaLight(std::size_t light, const RenderTarget& target, gl::PassProfiler& profiler);

  CoverageSettings coverage_;
  SurfaceLighting surface_lighting_;
  const GpuScene* scene_ = nullptr;
  std::vector<AreaLight> lights_;
  int batch_ = 0;  // points per coverage draw
  int points_ = 0;
  float lift_ = 0;
  std::vector<gl::Buffer> light_buffers_;  // per light: its triangles, then its occluders
  std::optional<gl::LayeredTarget> coverage_layers_;  // 8-bit, a layer per point of a batch
  gl::VertexArray vertex_array_;
  gl::Program draw_program_, weigh_program_;
};

TechniqueInfo jitteredLightSamplingTechniqueInfo();

}  // namespace gib::rt
