#include "realtime/atlas/atlas_lighting.h"

#include "realtime/gl/pipeline_state.h"

namespace gib::rt::atlas {

AtlasLighting::AtlasLighting(const ShadowSettings& settings, const GpuScene& scene,
                             std::size_t most_samples)
    : shadow_maps_(settings, scene, shadowBatchCapacity(settings, most_samples)) {}

const gl::FullScreenPass& AtlasLighting::pass(LightSampleKind kind) {
  std::optional<gl::FullScreenPass>& slot = passes_[kind == LightSampleKind::kPoint ? 0 : 1];
  if (!slot) {
    slot.emplace("realtime/atlas/atlas_light.frag.glsl", shadow_maps_.defines(kind));
    shadow_maps_.setLookupConstants(slot->program());
  }
  return *slot;
}

void AtlasLighting::add(const GpuScene& scene, std::span<const LightSample> samples,
                        const AtlasTextures& atlas, const gl::Framebuffer& target) {
  for (std::span<const LightSample> batch : lightSampleBatches(samples, shadow_maps_.capacity())) {
    const gl::FullScreenPass& light = pass(batch.front().kind);
    shadow_maps_.render(scene, batch, unmeasured_);
    const gl::Program& program = light.program();
    program.use();
    shadow_maps_.bindForLookup(program);
    atlas.bind();
    target.bind();
    const gl::PipelineScope adding({
        .blend = gl::kAdditiveBlend,
        .viewport = gl::PixelRect{0, 0, atlas.resolution(), atlas.resolution()},
    });
    light.draw();
  }
}

}  // namespace gib::rt::atlas
