#include "realtime/techniques/environment_map/environment_map_technique.h"

#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/gpu_scene/glossy_exponents.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/render_target.h"
#include "scene/path_expression.h"
#include "scene/scene.h"

#include <fmt/format.h>

#include <memory>
#include <string>

namespace gib::rt {

namespace {

constexpr const char* kEnvironmentShader =
    "realtime/techniques/environment_map/environment.frag.glsl";

// The environment pass's defines: the map and the glossy layers' exponents.
std::string passDefines(const std::vector<float>& exponents) {
  std::string defines(kEnvironmentMapDefine);
  defines += fmt::format("#define GLOSSY_MAPS {}\n", exponents.size());
  if (!exponents.empty())
    defines += fmt::format("#define GLOSSY_EXPONENTS {}\n", glslExponentArray(exponents));
  return defines;
}

}  // namespace

EnvironmentMapTechnique::EnvironmentMapTechnique(const ParameterValues& p)
    : surface_lighting_(p),
      irradiance_resolution_(p.integer("irradiance_resolution")),
      source_resolution_(p.integer("source_resolution")),
      fresnel_schlick_(p.text("fresnel") == "schlick") {}

scene::PathClass EnvironmentMapTechnique::pathClass() const {
  return scene::PathClass::ofExpression(
      scene::PathExpression::parse(kEnvironmentMapPathExpression).text());
}

void EnvironmentMapTechnique::prepare(const GpuScene& scene, int width, int height) {
  scene_ = &scene;
  // The environment's light is this technique's own (§4.2.2, without visibility), not the
  // shared light samples' (shadow-mapped directions of the sky or the map).
  surface_lighting_.lighting().setEnvironmentSamples(false);
  surface_lighting_.prepare(scene, width, height);
  environment_ = surface_lighting_.lighting().environment();
  if (!environment_) {
    // A constant sky (the need admits one) is a constant map: the same lookups and sums.
    constant_sky_.emplace(sceneEnvironment(scene.scene()));
    environment_ = &*constant_sky_;
  }
  const std::vector<float> exponents = glossyExponents(scene.scene());
  convolution_.emplace(environment_->map(), source_resolution_, irradiance_resolution_, exponents);
  pass_ = gl::FullScreenPass(kEnvironmentShader, passDefines(exponents));
  environment_->setUniforms(pass_.program());
  pass_.program().set("u_fresnel_schlick", fresnel_schlick_ ? 1 : 0);
  pass_.program().set("u_normals_face_viewer", 0);  // the camera's G-buffer
}

void EnvironmentMapTechnique::render(Frame& frame) {
  surface_lighting_.render(*scene_, frame.target, frame.profiler);
  auto pass = frame.profiler.pass(kEnvironmentPass);
  pass_.use();
  scene_->bindSceneBuffers();
  surface_lighting_.gbuffer().bindTextures();
  environment_->bind();
  convolution_->bind();
  // Added to the emission and the scene's lights (zero at a mirror or glass pixel, whose diffuse
  // reflectance is black).
  const gl::PipelineScope adding({.blend = gl::kAdditiveBlend});
  frame.target.bind();
  pass_.draw();
}

std::vector<AuxiliaryImage> EnvironmentMapTechnique::auxiliaryImages() {
  return {{"irradiance_map",
           "the irradiance E(n) (W/m²) of every normal direction, laid out as the environment "
           "map but with rows from pole to pole inclusive (row 0 the zenith, the last the nadir)",
           convolution_->layerImage(0, environment_->map().intensity)}};
}

std::vector<TechniqueStatistic> EnvironmentMapTechnique::statistics() const {
  return {{"prepare_convolution_ms", convolution_->milliseconds()},
          {"source_texels", double(convolution_->sourceTexels())},
          {"convolved_texels", double(convolution_->convolvedTexels())},
          {"texels_summed",
           double(convolution_->sourceTexels()) * double(convolution_->convolvedTexels())},
          {"glossy_maps", double(convolution_->layers() - 1)}};
}

TechniqueInfo environmentMapTechniqueInfo() {
  TechniqueInfo info;
  info.name = "environment_map";
  info.description =
      "image-based lighting without visibility: mirrors and glass reflect and refract the "
      "environment map, diffuse and glossy surfaces read its convolved maps";
  info.source =
      "Szirmay-Kalos et al., GPU-Based Techniques for Global Illumination Effects, §4.2.1-4.2.2 "
      "and Figs. 4.9-4.12";
  info.parameters = joinParameterTables(
      {{numericParameter("irradiance_resolution", ParameterType::kInteger, "32", 8, 128, "texels",
                         "rows of the convolved latitude-longitude maps (twice as many "
                         "columns): irradiance by normal, glossy lobe by reflected direction"),
        numericParameter("source_resolution", ParameterType::kInteger, "64", 8, 256, "texels",
                         "rows of the resampled environment the convolution sums (its error "
                         "falls as their square)"),
        choiceParameter("fresnel", "schlick", {"schlick", "exact"},
                        "Fresnel's function: eq. 1.6's approximation as the book, or the exact "
                        "one the reference uses")},
       SurfaceLighting::parameters()});
  SurfaceLighting::declarePasses(info.passes);
  info.passes.add(passPath({kFramePass, kEnvironmentPass}),
                  "the environment's light added at every pixel: mirrors and glass by their "
                  "reflected and refracted rays, diffuse and glossy surfaces from the convolved "
                  "maps");
  info.auxiliary_images = {
      {"irradiance_map", "the convolved irradiance of every normal direction (W/m²)"}};
  info.statistics = {
      {"prepare_convolution_ms",
       "time to resample the environment and sum the convolved maps (prepare)"},
      {"source_texels", "cells of the resampled environment each convolved texel sums"},
      {"convolved_texels", "texels of the irradiance map and the glossy maps"},
      {"texels_summed", "terms of the convolution: source texels × convolved texels"},
      {"glossy_maps", "glossy maps, one per distinct Phong exponent of the scene"}};
  // Mirrors and glass where the scene has them, diffuse and glossy objects alone too (Figs. 4.11,
  // 4.12).
  info.needs = {TechniqueNeed::kEnvironmentLight};
  info.renders_specular_materials = true;
  info.renders_environment_map = true;
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<EnvironmentMapTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
