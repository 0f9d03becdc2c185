// `hemispherical_gather`: one bounce of indirect light gathered by the rasterizer (Fournier &
// Péroche §5): the directly lit scene (a radiance atlas, ρ/π times the shadow-mapped direct
// irradiance) is rendered around sparse gather points of the image, a 160° perspective view or
// a fish-eye (hemispherical) view of the tessellated scene, one layer per point and one instanced
// draw per batch; a compute pass sums each view into irradiance, and a full-screen pass
// interpolates it to every pixel. Direct light and emission as `direct` renders them. See
// README.md beside this file.
#pragma once

#include "realtime/atlas/atlas_mesh.h"
#include "realtime/atlas/direct_radiance_atlas.h"
#include "realtime/gbuffer/gbuffer.h"
#include "realtime/gl/fullscreen_pass.h"
#include "realtime/lighting/surface_lighting.h"
#include "realtime/technique.h"
#include "realtime/techniques/hemispherical_gather/hemisphere_gather.h"
#include "realtime/techniques/hemispherical_gather/voxel_slices.h"

#include <optional>

namespace gib::rt {

class HemisphericalGatherTechnique final : public Technique {
 public:
  explicit HemisphericalGatherTechnique(const ParameterValues& parameters);

  void prepare(const GpuScene& scene, int width, int height) override;
  void render(Frame& frame) override;
  scene::PathClass pathClass() const override { return {0, 2}; }
  std::vector<AuxiliaryImage> auxiliaryImages() override;
  std::vector<TechniqueStatistic> statistics() const override;

 private:
  int projection_;  // gpu::kProjection*
  int view_size_;
  int spacing_;
  int atlas_resolution_;
  int tessellation_;
  int light_samples_;
  int slices_;
  int slice_size_;
  SurfaceLighting surface_lighting_;
  const GpuScene* scene_ = nullptr;
  atlas::DirectRadianceAtlas atlas_;
  std::optional<atlas::AtlasMesh> mesh_;
  std::optional<VoxelSlices> voxels_;
  std::optional<HemisphereGather> gather_;
  gl::FullScreenPass interpolate_;
};

TechniqueInfo hemisphericalGatherTechniqueInfo();

}  // namespace gib::rt
