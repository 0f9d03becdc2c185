#include "realtime/techniques/direct/direct_lighting.h"

#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/shader_library.h"

#include <glm/gtc/type_ptr.hpp>

namespace gib::rt {

DirectLighting::DirectLighting(const ShadowSettings& settings, int light_samples)
    : shadow_settings_(settings), light_samples_(light_samples) {}

void DirectLighting::prepare(const GpuScene& scene) {
  // Points on emitters sit a hair in front of them, beyond the cube maps' near plane.
  const float extent = glm::length(scene.boundsMax() - scene.boundsMin());
  samples_ = makeLightSamples(scene.scene(), scene.emitters(), light_samples_, light_samples_,
                              1e-3f * extent);
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

void DirectLighting::drawFullScreen(const RenderTarget& target) const {
  target.bind();
  empty_vertex_array_.bind();
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void DirectLighting::writeEmission(const GpuScene& scene, const GBuffer& gbuffer,
                                   const RenderTarget& target, gl::PassProfiler& profiler) {
  auto pass = profiler.pass("emission");
  scene.bindSceneBuffers();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  gbuffer.bindTextures(0);
  emission_.use();
  drawFullScreen(target);
}

void DirectLighting::addDirect(const GpuScene& scene, const std::vector<LitView>& views,
                               gl::PassProfiler& profiler) {
  auto lights = profiler.pass("lights");
  for (LightSample sample : samples_) {
    if (sample.kind == LightSampleKind::kPoint) sample.position += light_offset_;
    shadow_maps_->render(scene, sample, profiler);
    scene.bindSceneBuffers();
    for (const LitView& view : views) {
      auto pass = profiler.pass(view.pass);
      const gl::Program& program = shadeProgram(sample.kind);
      program.use();
      view.gbuffer->bindTextures(0);
      shadow_maps_->bindForLookup(program, sample);
      glUniform3fv(program.uniform("u_light_intensity"), 1, glm::value_ptr(sample.intensity));
      glUniform1f(program.uniform("u_cos_cone"), sample.cos_cone);
      glUniform1f(program.uniform("u_exponent"), sample.exponent);
      glUniform1i(program.uniform("u_normals_face_viewer"), view.normals_face_viewer ? 1 : 0);
      glDisable(GL_DEPTH_TEST);
      glEnable(GL_BLEND);
      glBlendFunc(GL_ONE, GL_ONE);  // each sample adds its share of the direct light
      drawFullScreen(*view.target);
      glDisable(GL_BLEND);
    }
  }
}

}  // namespace gib::rt
