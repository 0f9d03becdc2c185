// `irradiance_volume`: progressive multi-bounce diffuse (and Phong-lobe) indirect light from
// cube maps at the points of a uniform grid projected to spherical harmonics (Nijasure, Pattanaik
// & Goel 2005). Each frame: rasterise the probes' cube maps into a G-buffer atlas (once, when only
// the light moves), light them with `direct`'s shadow-mapped light samples, then per bounce
// project them to SH (eq. 2) and relight them with the interpolated indirect light (eq. 3-6);
// the camera view gets direct light plus the last bounce's indirect light. See README.md beside
// this file.
#pragma once

#include "realtime/gbuffer/gbuffer.h"
#include "realtime/gl/fullscreen_pass.h"
#include "realtime/gl/objects.h"
#include "realtime/lighting/surface_lighting.h"
#include "realtime/technique.h"
#include "realtime/techniques/irradiance_volume/probe_grid.h"

#include <optional>
#include <string_view>

namespace gib::rt {

// The passes of a frame, as Table 1's rows (irradiance_volume_technique.cpp declares them).
inline constexpr std::string_view kRasteriseProbesPass = "rasterise cube maps";
inline constexpr std::string_view kProbeDirectPass = "probe direct light";  // inside kLightsPass
inline constexpr std::string_view kShProjectionPass = "sh projection";
inline constexpr std::string_view kRelightProbesPass = "relight cube maps";
inline constexpr std::string_view kIndirectPass = "indirect";

class IrradianceVolumeTechnique final : public Technique {
 public:
  explicit IrradianceVolumeTechnique(const ParameterValues& parameters);

  void prepare(const GpuScene& scene, int width, int height) override;
  void render(Frame& frame) override;
  // k bounces of indirect light on top of direct light: paths of up to k + 1 bounces.
  scene::PathClass pathClass() const override { return {0, bounces_ + 1}; }
  std::vector<AuxiliaryImage> auxiliaryImages() override;
  std::vector<TechniqueStatistic> statistics() const override;

 private:
  // Coefficients of the probes' incident radiance from `lit` (the atlas lit so far).
  void project(const RenderTarget& lit);
  // Adds the indirect light of the current coefficients into `target` over `gbuffer`.
  void addIndirect(const GBuffer& gbuffer, const RenderTarget& target, bool probe_view);
  // The bounces after the direct light: coefficients of bounce k at the end. `after_bounce`
  // (optional) is called with the bounce number once its coefficients are ready.
  void bounce(gl::PassProfiler& profiler, const std::function<void(int)>& after_bounce = {});
  void rasteriseProbes();
  glm::vec3 lightOffset(const Frame& frame) const;

  int bounces_, grid_n_, face_, band_;
  bool indirect_shadows_, rasterise_every_frame_, objects_bounds_;
  SurfaceLighting surface_lighting_;
  const GpuScene* scene_ = nullptr;
  ProbeGrid grid_;
  float near_ = 0, far_ = 0;
  bool rasterised_ = false;
  std::optional<GBuffer> probe_gbuffer_;
  std::optional<RenderTarget> probe_direct_, probe_lit_;
  gl::Buffer coefficients_, weights_, phong_factors_;
  gl::Texture coefficient_texels_;  // coefficients_ as a buffer texture, for the lookups
  gl::Program project_;
  gl::FullScreenPass indirect_;
};

TechniqueInfo irradianceVolumeTechniqueInfo();

}  // namespace gib::rt
