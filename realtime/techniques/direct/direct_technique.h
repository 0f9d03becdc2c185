// `direct`: direct illumination only (path class LE + LDE) from every light of the scene model
// with shadow maps (book Ch. 4): hard, percentage-closer filtered or variance shadow maps; area
// lights and the sky as many light samples, a shadow map each, so that the image converges to the
// exact direct illumination as the sample count grows. Deferred: one g-buffer pass, then per
// light sample a shadow map and a full-screen shading pass added into the frame.
#pragma once

#include "realtime/gbuffer.h"
#include "realtime/technique.h"
#include "realtime/techniques/direct/light_samples.h"
#include "realtime/techniques/direct/shadow_maps.h"

#include <memory>
#include <optional>

namespace gib::rt {

class DirectTechnique final : public Technique {
 public:
  explicit DirectTechnique(const ParameterValues& parameters);

  void prepare(const GpuScene& scene, int width, int height) override;
  void render(Frame& frame) override;
  scene::PathClass pathClass() const override { return {0, 1}; }

  std::size_t lightSampleCount() const { return samples_.size(); }

 private:
  const gl::Program& shadeProgram(LightSampleKind kind) const {
    return kind == LightSampleKind::kPoint ? shade_point_ : shade_directional_;
  }

  ShadowSettings shadow_settings_;
  int light_samples_;
  const GpuScene* scene_ = nullptr;
  std::vector<LightSample> samples_;
  std::optional<GBuffer> gbuffer_;
  std::optional<ShadowMaps> shadow_maps_;
  gl::Program emission_, shade_point_, shade_directional_;
  gl::VertexArray empty_vertex_array_;  // core profile draws need one bound
};

TechniqueInfo directTechniqueInfo();

}  // namespace gib::rt
