// `distance_map_specular`: mirror and glass objects that reflect and refract their environment
// through distance maps (book Ch. 6: §6.1 the searches, §6.2 single reflections and refractions,
// §6.3 inter-object reflections, §6.8's map size). The frame is `direct`'s (SurfaceLighting:
// G-buffer, emission, shadow-mapped light samples) with the maps' views lit by the same batches;
// then the maps are composed (`rounds` rounds, each adding a specular bounce between objects)
// and every mirror or glass pixel traces its rays through its object's map by `search`. Path
// class L D? S{0,2·rounds} E (a glass's way through is two vertices). See README.md beside this
// file.
#pragma once

#include "realtime/distance_map/distance_map_frame.h"
#include "realtime/distance_map/distance_maps.h"
#include "realtime/gl/fullscreen_pass.h"
#include "realtime/gl/objects.h"
#include "realtime/lighting/surface_lighting.h"
#include "realtime/technique.h"

#include <optional>
#include <string_view>
#include <vector>

namespace gib::rt {

inline constexpr std::string_view kSpecularPass = "specular";

class DistanceMapSpecularTechnique final : public Technique {
 public:
  explicit DistanceMapSpecularTechnique(const ParameterValues& parameters);

  void provide(const TechniqueServices& services) override { services_ = services; }
  void prepare(const GpuScene& scene, int width, int height) override;
  void render(Frame& frame) override;
  scene::PathClass pathClass() const override;
  std::vector<AuxiliaryImage> auxiliaryImages() override;
  std::vector<TechniqueStatistic> statistics() const override;
  std::vector<TechniqueStatistic> finalStatistics() const override;
  std::optional<image::Image> measuredRegion() override;

 private:
  // The specular pass (`specular_`, or `capture_` with its hit and ray targets) into the bound
  // framebuffer.
  void drawSpecular(const gl::FullScreenPass& pass) const;
  // The search_error image: per mirror or glass pixel, the distance between the hit the search
  // found and the first hit Embree finds on the same ray among the surfaces the map holds.
  image::Image searchError();

  SurfaceLighting surface_lighting_;
  int resolution_, rounds_;
  ReferencePoint reference_point_;
  DistanceMapSearch search_;
  TechniqueServices services_;
  const GpuScene* scene_ = nullptr;
  std::optional<DistanceMaps> maps_;
  gl::FullScreenPass specular_, capture_;
  double search_error_mean_ = 0, search_error_max_ = 0;
  bool search_error_measured_ = false;
};

// "LD?S{0,2·rounds}E": emitters and the diffuse surfaces' direct light seen directly or through up
// to `rounds` objects, a mirror one specular vertex and a glass two.
std::string distanceMapSpecularPathExpression(int rounds);

TechniqueInfo distanceMapSpecularTechniqueInfo();

}  // namespace gib::rt
