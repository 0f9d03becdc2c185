// `direct`: direct illumination only (path class LE|LDE) from every light of the scene model
// with shadow maps (book Ch. 4): hard, percentage-closer filtered or variance shadow maps; area
// lights and the sky as many light samples, a shadow map each, so that the image converges to the
// exact direct illumination as the sample count grows. Deferred: one g-buffer pass, then per
// batch of up to 32 light samples their shadow maps (the layers of one array texture, drawn by
// one multi-draw) and one full-screen shading pass that loops over the batch, added into the
// frame. The lighting itself is the shared realtime/lighting/ block; see README.md beside this
// file.
#pragma once

#include "realtime/lighting/surface_lighting.h"
#include "realtime/technique.h"

namespace gib::rt {

class DirectTechnique final : public Technique {
 public:
  explicit DirectTechnique(const ParameterValues& parameters);

  void prepare(const GpuScene& scene, int width, int height) override;
  void render(Frame& frame) override;
  scene::PathClass pathClass() const override { return {0, 1}; }

  std::size_t lightSampleCount() const { return surface_lighting_.lighting().sampleCount(); }

 private:
  SurfaceLighting surface_lighting_;
  const GpuScene* scene_ = nullptr;
};

TechniqueInfo directTechniqueInfo();

}  // namespace gib::rt
