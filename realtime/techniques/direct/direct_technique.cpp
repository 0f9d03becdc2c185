#include "realtime/techniques/direct/direct_technique.h"

namespace gib::rt {

DirectTechnique::DirectTechnique(const ParameterValues& p)
    : lighting_(shadowSettings(p), p.integer("light_samples")) {}

void DirectTechnique::prepare(const GpuScene& scene, int width, int height) {
  scene_ = &scene;
  gbuffer_.emplace(width, height);
  lighting_.prepare(scene);
}

void DirectTechnique::render(Frame& frame) {
  const GpuScene& scene = *scene_;
  gbuffer_->render(scene, &frame.profiler);
  lighting_.writeEmission(scene, *gbuffer_, frame.target, frame.profiler);
  lighting_.addDirect(scene, {{&*gbuffer_, &frame.target}}, frame.profiler);
}

TechniqueInfo directTechniqueInfo() {
  TechniqueInfo info;
  info.name = "direct";
  info.description =
      "direct illumination (LE + LDE) with shadow maps: hard, PCF or variance; area lights and "
      "sky by light samples";
  info.source = "Szirmay-Kalos et al., GPU-Based Techniques for Global Illumination Effects, Ch. 4";
  info.parameters = directLightingParameters();
  info.passes.add(passPath({kFramePass, kGBufferPass}), "what each pixel's primary ray hits");
  DirectLighting::declarePasses(info.passes, kFramePass);
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<DirectTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
