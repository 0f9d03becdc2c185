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

DirectTechnique::DirectTechnique(const ParameterValues& p)
    : light_samples_(p.integer("light_samples")) {
  shadow_settings_.filter = parseFilter(p.text("shadow"));
  shadow_settings_.size = p.integer("shadow_map_size");
  shadow_settings_.pcf_radius = p.integer("pcf_radius");
  shadow_settings_.normal_offset = float(p.number("normal_offset"));
  shadow_settings_.blur_radius = p.integer("vsm_blur_radius");
  shadow_settings_.min_variance = float(p.number("vsm_min_variance"));
}

void DirectTechnique::prepare(const GpuScene& scene, int width, int height) {
  scene_ = &scene;
  // Points on emitters sit a hair in front of them, beyond the cube maps' near plane.
  const float extent = glm::length(scene.boundsMax() - scene.boundsMin());
  samples_ = makeLightSamples(scene.scene(), scene.emitters(), light_samples_, light_samples_,
                              1e-3f * extent);
  gbuffer_.emplace(width, height);
  shadow_maps_.emplace(shadow_settings_, scene);
  emission_ = gl::buildProgram({{GL_VERTEX_SHADER, "shaders/fullscreen.vert.glsl"},
                                {GL_FRAGMENT_SHADER, "techniques/direct/emission.frag.glsl"}});
  auto shade = [&](LightSampleKind kind) {
    return gl::buildProgram({{GL_VERTEX_SHADER, "shaders/fullscreen.vert.glsl"},
                             {GL_FRAGMENT_SHADER, "techniques/direct/shade_light.frag.glsl"}},
                            shadow_maps_->defines(kind));
  };
  shade_point_ = shade(LightSampleKind::kPoint);
  shade_directional_ = shade(LightSampleKind::kDirectional);
  shadow_maps_->setLookupConstants(shade_point_);
  shadow_maps_->setLookupConstants(shade_directional_);
  glProgramUniform3fv(emission_.id(), emission_.uniform("u_sky_radiance"), 1,
                      glm::value_ptr(scene.scene().sky_radiance));
}

void DirectTechnique::render(Frame& frame) {
  const GpuScene& scene = *scene_;
  gl::PassProfiler& profiler = frame.profiler;
  gbuffer_->render(scene, &profiler);
  scene.bindSceneBuffers();

  auto drawFullScreen = [&] {
    frame.target.bind();
    empty_vertex_array_.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
  };
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  {
    auto pass = profiler.pass("emission");
    gbuffer_->bindTextures(0);
    emission_.use();
    drawFullScreen();
  }
  auto lights = profiler.pass("lights");
  for (const LightSample& sample : samples_) {
    shadow_maps_->render(scene, sample, profiler);
    auto pass = profiler.pass("shading");
    const gl::Program& program = shadeProgram(sample.kind);
    program.use();
    gbuffer_->bindTextures(0);
    shadow_maps_->bindForLookup(program, sample);
    glUniform3fv(program.uniform("u_light_intensity"), 1, glm::value_ptr(sample.intensity));
    glUniform1f(program.uniform("u_cos_cone"), sample.cos_cone);
    glUniform1f(program.uniform("u_exponent"), sample.exponent);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);  // each sample adds its share of the direct light
    drawFullScreen();
    glDisable(GL_BLEND);
  }
}

TechniqueInfo directTechniqueInfo() {
  TechniqueInfo info;
  info.name = "direct";
  info.description =
      "direct illumination (LE + LDE) with shadow maps: hard, PCF or variance; area lights and "
      "sky by light samples";
  info.source = "Szirmay-Kalos et al., GPU-Based Techniques for Global Illumination Effects, Ch. 4";
  info.parameters = {
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
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<DirectTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
