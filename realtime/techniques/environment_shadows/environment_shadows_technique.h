// `environment_shadows`: diffuse and glossy reflections of an environment map with shadows (book
// §4.2.3, Figs. 4.13-4.15). The sphere of directions is split into cells of roughly equal power
// (realtime/environment_cells/: radiance-proportional centres, weighted Lloyd relaxation), and
// every cell becomes a directional light at its centre carrying the cell's total incoming
// radiance, with its own shadow map: the frame of `direct` (SurfaceLighting: G-buffer, emission
// showing the map, the scene's lights) with the cells in place of its sky samples. The BRDF is
// taken at the cell's centre (reflectivity=center) or averaged over the cell as a cap
// (reflectivity=integrated, Fig. 4.14). Path class LE|LDE. See README.md beside this file.
#pragma once

#include "realtime/environment_cells/environment_cells.h"
#include "realtime/gl/objects.h"
#include "realtime/lighting/surface_lighting.h"
#include "realtime/technique.h"

#include <optional>
#include <vector>

namespace gib::rt {

class EnvironmentShadowsTechnique final : public Technique {
 public:
  explicit EnvironmentShadowsTechnique(const ParameterValues& parameters);

  void prepare(const GpuScene& scene, int width, int height) override;
  void render(Frame& frame) override;
  scene::PathClass pathClass() const override { return {0, 1}; }
  std::vector<AuxiliaryImage> auxiliaryImages() override;
  std::vector<TechniqueStatistic> statistics() const override;

  const EnvironmentCells& cells() const { return cells_; }
  std::size_t lightSampleCount() const { return surface_lighting_.lighting().sampleCount(); }

 private:
  // The reflectivity tables and the shading passes' defines (reflectivity=integrated).
  void prepareReflectivity(const scene::Scene& scene);

  SurfaceLighting surface_lighting_;
  int cell_count_, relaxation_steps_;
  bool integrated_;
  const GpuScene* scene_ = nullptr;
  scene::EnvironmentMap map_;
  EnvironmentCells cells_;
  SphericalDelaunay triangulation_;
  double delaunay_ms_ = 0, reflectivity_ms_ = 0;
  gl::Texture reflectivity_;
};

TechniqueInfo environmentShadowsTechniqueInfo();

}  // namespace gib::rt
