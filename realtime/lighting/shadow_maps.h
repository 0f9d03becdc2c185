// The shadow map of one light sample at a time (book §4.1): a cube of 90° faces around a point
// sample (the book's "six spot lights" for omnidirectional lights; faces the sample cannot light
// are cleared, not drawn), or an orthographic map over the scene's bounding sphere for a
// directional sample. Hard and PCF maps hold depth and are read with hardware comparison; a
// variance shadow map holds (d, d²), box-filtered by a compute pass.
#pragma once

#include "realtime/gl/objects.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/lighting/light_samples.h"
#include "realtime/pass_declarations.h"

#include <array>
#include <string_view>

namespace gib::rt {

namespace gl {
class PassProfiler;
}

enum class ShadowFilter { kHard, kPcf, kVariance };

// The passes ShadowMaps::render opens, inside its caller's pass.
inline constexpr std::string_view kShadowMapPass = "shadow map";
inline constexpr std::string_view kShadowMapFilterPass = "shadow map filter";  // variance only

struct ShadowSettings {
  ShadowFilter filter = ShadowFilter::kHard;
  int size = 512;           // texels per side (of each cube face)
  int pcf_radius = 0;       // PCF taps: (2r+1)² bilinear comparisons one texel apart
  float normal_offset = 1;  // receiver offset along its normal, in texels
  int blur_radius = 2;      // variance shadow map: (2r+1)² box, the book's 5×5
  float min_variance = 1e-6f;
};

class ShadowMaps {
 public:
  ShadowMaps(const ShadowSettings& settings, const GpuScene& scene);

  // Declares the passes of render() under `parent`.
  static void declarePasses(PassDeclarations& passes, std::string_view parent);

  // Renders the map of `sample` (inside the caller's profiler passes).
  void render(const GpuScene& scene, const LightSample& sample, gl::PassProfiler& profiler);
  // Sets the lookup uniforms of shadow_lookup.glsl that are the same for every sample (planes,
  // size, offsets, filter settings) in `program`; once, when the program is built.
  void setLookupConstants(const gl::Program& program) const;
  // Binds the map to kShadowMapUnit and sets the sample's own lookup uniforms (position, axis,
  // projection) of `program`, which must be the variant for the sample's kind.
  void bindForLookup(const gl::Program& program, const LightSample& sample) const;

  // The GLSL defines of this filter, for programs that read the map.
  std::string defines(LightSampleKind kind) const;

 private:
  void clear(const gl::Framebuffer& framebuffer) const;
  void renderCube(const GpuScene& scene, const LightSample& sample);
  void renderFlat(const GpuScene& scene, const LightSample& sample);
  void blur(LightSampleKind kind, gl::PassProfiler& profiler);
  glm::mat4 flatViewProjection(const LightSample& sample) const;

  ShadowSettings settings_;
  float near_, far_;  // cube faces
  glm::vec3 centre_;  // bounding sphere of the scene
  float radius_;
  gl::Program depth_point_, depth_flat_, blur_point_, blur_flat_;
  gl::Texture cube_depth_, cube_moments_, cube_scratch_;
  gl::Texture flat_depth_, flat_moments_, flat_scratch_;
  std::array<gl::Framebuffer, 6> cube_faces_;
  gl::Framebuffer flat_;
};

}  // namespace gib::rt
