// `distance_map_gather`: one diffuse or glossy object shaded by final gathering from a distance
// map (book §7.3, Figs. 7.10-7.13). The frame is `direct`'s (SurfaceLighting) with the map's
// views lit by the same batches (realtime/distance_map/); the map, taken at the object's centre
// or the scene's, is averaged down to M² texels per face, and every pixel of the object gathers
// every low-resolution texel as an area light of the texel's mean radiance at its mean distance,
// its solid angle carried from o to the pixel's point (eq. 7.7 or 7.6), without visibility. Or,
// with mode=irradiance_map, the classic irradiance environment map of §4.2.2 from the same map.
// Path class L D{0,2} E. See README.md beside this file.
#pragma once

#include "realtime/distance_map/distance_map_frame.h"
#include "realtime/distance_map/distance_maps.h"
#include "realtime/gl/fullscreen_pass.h"
#include "realtime/gl/objects.h"
#include "realtime/lighting/surface_lighting.h"
#include "realtime/ray_casting/gpu_ray_structure.h"
#include "realtime/technique.h"

#include <memory>
#include <optional>
#include <string_view>
#include <vector>

namespace gib::rt {

inline constexpr std::string_view kIrradianceConvolutionPass = "irradiance convolution";
inline constexpr std::string_view kFinalGatherPass = "gather";

class DistanceMapGatherTechnique final : public Technique {
 public:
  explicit DistanceMapGatherTechnique(const ParameterValues& parameters);

  void prepare(const GpuScene& scene, int width, int height) override;
  void render(Frame& frame) override;
  scene::PathClass pathClass() const override;
  std::vector<AuxiliaryImage> auxiliaryImages() override;
  std::vector<TechniqueStatistic> statistics() const override;
  std::vector<TechniqueStatistic> finalStatistics() const override;
  std::optional<image::Image> measuredRegion() override;

 private:
  // The object the parameter `object` names, checked (gib::InputError).
  DistanceMapObject chooseObject(const scene::Scene& scene) const;
  // The map averaged (and convolved, mode=irradiance_map) for the gather.
  void downsample();
  void convolveIrradiance();
  // The gather pass (`gather_`, or `capture_` with its texel counts) into the bound framebuffer.
  void drawGather(const gl::FullScreenPass& pass) const;

  SurfaceLighting surface_lighting_;
  int object_parameter_, resolution_, gather_size_, mode_, solid_angle_;
  bool peak_only_;
  // visibility=true: the scene's triangles in a BVH (realtime/ray_casting/) that the gather casts
  // a shadow ray through per texel, to measure what the book's omission of the test costs.
  bool visibility_;
  std::unique_ptr<GpuRayStructure> structure_;
  ReferencePoint reference_point_;
  const GpuScene* scene_ = nullptr;
  std::optional<DistanceMaps> maps_;
  gl::Texture low_res_, irradiance_;
  gl::Program irradiance_program_;
  gl::FullScreenPass gather_, capture_;
  float exponent_ = 1.0f;
  double texels_mean_ = 0, object_pixels_ = 0;
  bool measured_ = false;
};

// "LD{0,2}E": the emitters and the walls' direct light as the map holds them, gathered by the
// object (L D E, L D D E); the other surfaces' direct light.
inline constexpr std::string_view kDistanceMapGatherPathExpression = "LD{0,2}E";

TechniqueInfo distanceMapGatherTechniqueInfo();

}  // namespace gib::rt
