// One light sample at a time reflected into every atlas texel: its shadow map drawn, then its
// light reflected by each texel's front side (atlas_light.frag.glsl) added into an atlas-sized
// target. Stochastic radiosity injects its first bounce with it; light path maps connect every
// virtual light to the exit texels it sees with it. Work outside any frame (prepare time), so its
// passes are not profiled.
#pragma once

#include "realtime/atlas/atlas_textures.h"
#include "realtime/gl/fullscreen_pass.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/lighting/light_samples.h"
#include "realtime/lighting/shadow_maps.h"

#include <array>
#include <optional>

namespace gib::rt::atlas {

class AtlasLighting {
 public:
  AtlasLighting(const ShadowSettings& settings, const GpuScene& scene);

  // Draws `sample`'s shadow map and adds its reflected light into `target` (a framebuffer of the
  // atlas's size) by additive blending.
  void add(const GpuScene& scene, const LightSample& sample, const AtlasTextures& atlas,
           const gl::Framebuffer& target);

 private:
  // The pass for a kind of sample, built on first use (a technique may have only one kind).
  const gl::FullScreenPass& pass(LightSampleKind kind);

  ShadowMaps shadow_maps_;
  std::array<std::optional<gl::FullScreenPass>, 2> passes_;  // point, directional
  gl::PassProfiler unmeasured_;                              // passes outside a frame are no-ops
};

}  // namespace gib::rt::atlas
