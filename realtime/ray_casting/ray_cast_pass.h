// Casts a batch of rays through a GPU structure in one compute dispatch (cast_rays.comp.glsl):
// what `gibench raycast-bench` times and the tests compare with the CPU traversals.
#pragma once

#include "realtime/gl/objects.h"
#include "realtime/ray_casting/gpu_ray_structure.h"
#include "scene/ray_caster.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <span>
#include <vector>

namespace gib::rt {

// A ray as the pass reads it, in the set's coordinates (ivmRayOrigin).
struct CastRay {
  glm::vec3 origin{0.0f};
  float t_min = 0.0f;
  glm::vec3 direction{0.0f, 0.0f, 1.0f};
  float t_max = gpu::kRayInfinity;
};
static_assert(sizeof(CastRay) == 32);

// World-space rays (their origins moved by −set.origin, their segments from 0 to ∞) as a batch.
std::vector<CastRay> castRaysOf(const IvmTriangleSet& set, std::span<const scene::Ray> rays);

class RayCastPass {
 public:
  explicit RayCastPass(const GpuRayStructure& structure);
  // Uploads the rays (replacing the previous batch) and sizes the hits buffer.
  void setRays(const std::vector<CastRay>& rays);
  // Casts the uploaded rays; returns at once (the GPU works on).
  void cast() const;
  // The hits of the last cast (waits for it).
  std::vector<gpu::RayCastHit> hits() const;
  std::size_t rayCount() const { return count_; }

 private:
  const GpuRayStructure* structure_;
  gl::Program program_;
  gl::Buffer rays_, hits_;
  std::size_t count_ = 0;
};

}  // namespace gib::rt
