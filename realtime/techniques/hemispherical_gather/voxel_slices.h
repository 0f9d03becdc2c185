// The scene voxelised into slices (Fournier & Péroche §5.3): along each axis the scene's bounds
// are cut into `slices` slabs; each slab is drawn from each of its two sides by an orthographic
// view of the radiance-textured scene clipped to the slab, into a size² face: the radiance of the
// first surface met going into the slab, alpha 1 where there is one. Built once (prepare time):
// one instanced draw per face direction, a layer per slab. The paper's 64 slices of 64² at 128
// bits per texel in each direction are 6 · 64 · 64² · 16 bytes = 25 MB.
#pragma once

#include "realtime/atlas/atlas_mesh.h"
#include "realtime/gl/objects.h"
#include "realtime/gpu_scene/gpu_scene.h"

#include <glm/vec3.hpp>

namespace gib::rt {

class VoxelSlices {
 public:
  VoxelSlices(const GpuScene& scene, const atlas::AtlasMesh& mesh,
              const gl::Texture& radiance_atlas, int slices, int size);

  const gl::Texture& faces() const { return faces_; }  // RGBA32F, 6 · slices layers
  int slices() const { return slices_; }
  glm::vec3 boundsMin() const { return lo_; }
  glm::vec3 boundsMax() const { return hi_; }
  std::size_t bytes() const { return std::size_t(kFaces) * slices_ * size_ * size_ * 16; }
  double buildMilliseconds() const { return build_ms_; }
  // Sets the uniforms voxel_slices.glsl reads on `program`.
  void setLookupUniforms(const gl::Program& program) const;

 private:
  static constexpr int kFaces = 6;
  int slices_, size_;
  glm::vec3 lo_{0.0f}, hi_{0.0f};
  gl::Texture faces_;
  double build_ms_ = 0;
};

}  // namespace gib::rt
