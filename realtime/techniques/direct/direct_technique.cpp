#include "realtime/techniques/direct/direct_technique.h"

#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/shader_library.h"
#include "realtime/render_target.h"

#include <glm/gtc/type_ptr.hpp>

namespace gib::rt {

namespace {

ShadowFilter parseFilter(const std::string& name) {
  if (name == "pcf") return ShadowFilter::kPcf;
  if (name == "vsm") return ShadowFilter::kVariance;
  return ShadowFilter::kHard;
}

}  // namespace

ShadowSettings shadowSettings(const ParameterValues& p) {
  ShadowSettings settings;
  settings.filter = parseFilter(p.text("shadow"));
  settings.size = p.integer("shadow_map_size");
  settings.pcf_radius = p.integer("pcf_radius");
  settings.normal_offset = float(p.number("normal_offset"));
  settings.blur_radius = p.integer("vsm_blur_radius");
  settings.min_variance = float(p.number("vsm_min_variance"));
  return settings;
}

ParameterTable directLightingParameters() {
  return {
      choiceParameter("shadow", "hard", {"hard", "pcf", "vsm"},
                      "shadow map filter: nearest comparison, percentage-closer filtering, or "
                      "variance shadow map"),
      numericParameter("shadow_map_size", ParameterType::kInteger, "512", 16, 4096, "texels",
                       "shadow map resolution (each cube face for point lights)"),
      numericParameter("light_samples", ParameterType::kInteger, "16", 1, 4096, "",
                       "points over the area lights, and directions over the sky, each with its "
                       "own shadow map"),
      numericParameter("pcf_radius", ParameterType::kInteger, "0", 0, 4, "texels",
                       "PCF: (2r+1)² hardware-filtered comparisons; 0 is the book's 2×2 bilinear"),
      numericParameter("normal_offset", ParameterType::kNumber, "1", 0, 16, "texels",
                       "receiver offset along its normal against shadow acne"),
      numericParameter("vsm_blur_radius", ParameterType::kInteger, "2", 0, 8, "texels",
                       "variance shadow map box filter radius; 2 is the book's 5×5"),
      numericParameter("vsm_min_variance", ParameterType::kNumber, "1e-6", 0, 1, "",
                       "variance floor of the Chebyshev bound, in units of the light range²"),
  };
}

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
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<DirectTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
