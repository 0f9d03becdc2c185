// `environment_map`: image-based lighting without visibility (book §4.2.1-4.2.2). The frame is
// `direct`'s (SurfaceLighting: G-buffer, emission, the scene's lights with shadow maps) without
// the environment's light samples, the emission pass showing the environment map where camera
// rays leave the scene; then one pass adds
// the environment's light at every pixel: a mirror reflects the map's radiance in the reflected
// direction times Fresnel's function, a glass adds the radiance refracted through its front
// surface only, and diffuse and glossy surfaces read maps convolved when the technique is
// prepared (the irradiance by the normal, the Phong lobe's integral by the reflected direction).
// Path class L(D|S{1,2})?E. See README.md beside this file.
#pragma once

#include "realtime/gl/fullscreen_pass.h"
#include "realtime/lighting/environment_texture.h"
#include "realtime/lighting/surface_lighting.h"
#include "realtime/technique.h"
#include "realtime/techniques/environment_map/environment_convolution.h"

#include <optional>
#include <string_view>
#include <vector>

namespace gib::rt {

inline constexpr std::string_view kEnvironmentPass = "environment";

class EnvironmentMapTechnique final : public Technique {
 public:
  explicit EnvironmentMapTechnique(const ParameterValues& parameters);

  void prepare(const GpuScene& scene, int width, int height) override;
  void render(Frame& frame) override;
  scene::PathClass pathClass() const override;
  std::vector<AuxiliaryImage> auxiliaryImages() override;
  std::vector<TechniqueStatistic> statistics() const override;

 private:
  SurfaceLighting surface_lighting_;
  int irradiance_resolution_, source_resolution_;
  bool fresnel_schlick_;
  const GpuScene* scene_ = nullptr;
  // The map the pass reads: the emission pass's upload of the scene's map, or for a scene with a
  // constant sky a constant map of its own.
  std::optional<EnvironmentTexture> constant_sky_;
  const EnvironmentTexture* environment_ = nullptr;
  std::optional<EnvironmentConvolution> convolution_;
  gl::FullScreenPass pass_;
};

// "L(D|S{1,2})?E": emitters and the environment seen directly, the light of the scene's lights
// and of the environment reflected once by a diffuse or glossy surface, and the environment seen
// in a mirror (one specular vertex) or through a glass (two: the single refraction stands for the
// way in and out).
inline constexpr std::string_view kEnvironmentMapPathExpression = "L(D|S{1,2})?E";

TechniqueInfo environmentMapTechniqueInfo();

}  // namespace gib::rt
