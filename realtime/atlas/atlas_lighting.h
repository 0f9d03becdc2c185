// Light samples reflected into every atlas texel, a batch at a time: the batch's shadow maps
// drawn, then their light reflected by each texel's front side (atlas_light.frag.glsl) added
// into an atlas-sized target in one pass. Stochastic radiosity injects its first bounce with
// it; light path maps connect every virtual light to the exit texels it sees with it. Work
// outside any frame (prepare time), so its passes are not profiled.
#pragma once

#include "realtime/atlas/atlas_textures.h"
#include "realtime/gl/fullscreen_pass.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/lighting/light_samples.h"
#include "realtime/lighting/shadow_maps.h"

#include <array>
#include <optional>
#include <span>

namespace gib::rt::atlas {

class AtlasLighting {
 public:
  // `most_samples`: the largest number of samples one add() call will pass (sizes the batches).
  AtlasLighting(const ShadowSettings& settings, const GpuScene& scene, std::size_t most_samples);

  // Adds the light `samples` reflect into `target` (a framebuffer of the atlas's size) by
  // additive blending, a batch at a time.
  void add(const GpuScene& scene, std::span<const LightSample> samples, const AtlasTextures& atlas,
           const gl::Framebuffer& target);

 private:
  // The pass for a kind of sample, built on first use (a technique may have only one kind).
  const gl::FullScreenPass& pass(LightSampleKind kind);

  ShadowMaps shadow_maps_;
  std::array<std::optional<gl::FullScreenPass>, 2> passes_;  // point, directional
  gl::PassProfiler unmeasured_;                              // passes outside a frame are no-ops
};

}  // namespace gib::rt::atlas
