#include "realtime/lighting/direct_lighting.h"

#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/technique_parameters.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <numbers>

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
      lightSamplesParameter(),
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

void DirectLighting::declarePasses(
    PassDeclarations& passes, std::string_view parent,
    const std::vector<std::pair<std::string_view, std::string>>& view_passes) {
  const std::string lights = passPath({parent, kLightsPass});
  passes.add(passPath({parent, kEmissionPass}), "emitters and sky seen directly");
  passes.add(lights,
             "per batch of light samples: their shadow maps, then their light added into "
             "every view");
  ShadowMaps::declarePasses(passes, lights);
  passes.add(passPath({lights, kShadingPass}), "light added into the camera view");
  for (const auto& [name, description] : view_passes)
    passes.add(passPath({lights, name}), description);
}

DirectLighting::DirectLighting(const ShadowSettings& settings, int light_samples, bool area_lights)
    : shadow_settings_(settings), light_samples_(light_samples), area_lights_(area_lights) {}

void DirectLighting::prepare(const GpuScene& scene) {
  // Points on emitters sit a hair in front of them, beyond the cube maps' near plane.
  const float extent = glm::length(scene.boundsMax() - scene.boundsMin());
  samples_ = makeLightSamples(
      scene.scene(), area_lights_ ? scene.emitters() : std::vector<EmitterTriangle>{},
      light_samples_, environment_samples_ ? light_samples_ : 0, 1e-3f * extent);
  samples_.insert(samples_.end(), extra_samples_.begin(), extra_samples_.end());
  shadow_maps_.emplace(shadow_settings_, scene,
                       shadowBatchCapacity(shadow_settings_, samples_.size()));
  // Where camera rays leave a scene with an environment map, the pass shows the map (book
  // §4.2); a scene without one keeps the constant sky's program, so its image is unchanged.
  if (!scene.scene().environment.empty()) environment_.emplace(scene.scene().environment);
  emission_ = gl::FullScreenPass("realtime/lighting/emission.frag.glsl",
                                 environment_ ? kEnvironmentMapDefine : "");
  shade_point_ =
      gl::FullScreenPass("realtime/lighting/shade_light.frag.glsl",
                         shadow_maps_->defines(LightSampleKind::kPoint) + shading_defines_);
  shade_directional_ =
      gl::FullScreenPass("realtime/lighting/shade_light.frag.glsl",
                         shadow_maps_->defines(LightSampleKind::kDirectional) + shading_defines_);
  shadow_maps_->setLookupConstants(shade_point_.program());
  shadow_maps_->setLookupConstants(shade_directional_.program());
  if (environment_) {
    environment_->setUniforms(emission_.program());
  } else {
    emission_.program().set("u_sky_radiance", scene.scene().sky_radiance);
  }
}

void DirectLighting::writeEmission(const GpuScene& scene, const GBuffer& gbuffer,
                                   const RenderTarget& target, gl::PassProfiler& profiler) {
  auto pass = profiler.pass(kEmissionPass);
  scene.bindSceneBuffers();
  gbuffer.bindTextures();
  if (environment_) environment_->bind();
  target.bind();
  emission_.draw();  // in the default state: no depth test, no blending
}

void DirectLighting::addDirect(const GpuScene& scene, const std::vector<LitView>& views,
                               gl::PassProfiler& profiler, const AfterBatch& after_batch) {
  auto lights = profiler.pass(kLightsPass);
  std::vector<LightSample> moved = samples_;
  for (LightSample& sample : moved)
    if (sample.kind == LightSampleKind::kPoint) sample.position += light_offset_;
  for (std::span<const LightSample> batch : lightSampleBatches(moved, shadow_maps_->capacity())) {
    shadow_maps_->render(scene, batch, profiler);
    scene.bindSceneBuffers();
    const gl::FullScreenPass& shade = shadePass(batch.front().kind);
    const gl::Program& program = shade.program();
    for (const LitView& view : views) {
      auto pass = profiler.pass(view.pass);
      program.use();
      view.gbuffer->bindTextures();
      shadow_maps_->bindForLookup(program);
      program.set("u_normals_face_viewer", view.normals_face_viewer ? 1 : 0);
      // Each batch adds its share of the direct light.
      const gl::PipelineScope adding({.blend = gl::kAdditiveBlend});
      view.target->bind();
      shade.draw();
    }
    if (after_batch) after_batch(*shadow_maps_);
  }
}

glm::vec3 movingLightOffset(const GpuScene& scene, const Frame& frame) {
  if (frame.frames_left == 0) return glm::vec3(0.0f);
  const float phase =
      2.0f * std::numbers::pi_v<float> * float(frame.frames_left) / float(frame.frame_count);
  const float radius = 0.05f * glm::length(scene.boundsMax() - scene.boundsMin());
  return radius * glm::vec3(std::sin(phase), 0.0f, 1.0f - std::cos(phase));
}

}  // namespace gib::rt
