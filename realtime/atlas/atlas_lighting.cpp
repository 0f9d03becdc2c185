#include "realtime/atlas/atlas_lighting.h"

namespace gib::rt::atlas {

AtlasLighting::AtlasLighting(const ShadowSettings& settings, const GpuScene& scene)
    : shadow_maps_(settings, scene) {}

const gl::FullScreenPass& AtlasLighting::pass(LightSampleKind kind) {
  std::optional<gl::FullScreenPass>& slot = passes_[kind == LightSampleKind::kPoint ? 0 : 1];
  if (!slot) {
    slot.emplace("realtime/atlas/atlas_light.frag.glsl", shadow_maps_.defines(kind));
    shadow_maps_.setLookupConstants(slot->program());
  }
  return *slot;
}

void AtlasLighting::add(const GpuScene& scene, const LightSample& sample,
                        const AtlasTextures& atlas, const gl::Framebuffer& target) {
  const gl::FullScreenPass& light = pass(sample.kind);
  shadow_maps_.render(scene, sample, unmeasured_);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_DEPTH_TEST);
  const gl::Program& program = light.program();
  program.use();
  shadow_maps_.bindForLookup(program, sample);
  setLightSampleUniforms(program, sample);
  atlas.bind();
  target.bind();
  glViewport(0, 0, atlas.resolution(), atlas.resolution());
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  light.draw();
  glDisable(GL_BLEND);
}

}  // namespace gib::rt::atlas
