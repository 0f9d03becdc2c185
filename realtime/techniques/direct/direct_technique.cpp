#include "realtime/techniques/direct/direct_technique.h"

namespace gib::rt {

DirectTechnique::DirectTechnique(const ParameterValues& p) : surface_lighting_(p) {}

void DirectTechnique::prepare(const GpuScene& scene, int width, int height) {
  scene_ = &scene;
  surface_lighting_.prepare(scene, width, height);
}

void DirectTechnique::render(Frame& frame) {
  surface_lighting_.render(*scene_, frame.target, frame.profiler);
}

TechniqueInfo directTechniqueInfo() {
  TechniqueInfo info;
  info.name = "direct";
  info.description =
      "direct illumination (LE|LDE) with shadow maps: hard, PCF or variance; area lights and "
      "sky by light samples";
  info.source = "Szirmay-Kalos et al., GPU-Based Techniques for Global Illumination Effects, Ch. 4";
  info.parameters = SurfaceLighting::parameters();
  SurfaceLighting::declarePasses(info.passes);
  // An environment map is lit by light samples drawn from it and shown as the background, both by
  // the shared surface lighting (§4.2.3's directional decomposition, with shadows).
  info.renders_environment_map = true;
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<DirectTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
