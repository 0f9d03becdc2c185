// The scene's triangles in an Embree 3 BVH, and the two queries the tracer needs. Embree is
// included only in reference/*.cpp (docs/architecture.md, "Layers"); this header hides it.
#pragma once

#include "scene/ray_caster.h"
#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <vector>

namespace gib::ref {

// The closest hit of a ray: the scene layer's record, which the ray-caster interface shares.
using Hit = scene::RayHit;

class EmbreeScene {
 public:
  // Builds the BVH (robust mode, so that closed meshes are watertight). Embree errors go through
  // one device callback and end up as std::runtime_error.
  explicit EmbreeScene(const scene::Scene& scene);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Closest hit along origin + t·direction for t in (t_near, t_far); `direction` need not be unit.
  Hit intersect(const glm::vec3& origin, const glm::vec3& direction, float t_near = 0.0f,
                float t_far = std::numeric_limits<float>::infinity()) const;
  // Whether anything lies along the segment (t_near, t_far).
  bool occluded(const glm::vec3& origin, const glm::vec3& direction, float t_near,
                float t_far) const;
  // The same for a batch, through Embree's ray streams (rtcIntersect1M, rtcOccluded1M), which
  // trace rays in packets; `coherent` tells Embree the rays share an origin or a direction.
  void intersect(std::span<const scene::Ray> rays, std::span<Hit> hits, bool coherent) const;
  void occluded(std::span<const scene::Ray> rays, std::span<std::uint8_t> blocked) const;

  // An offset for spawned rays that keeps them off the surface they leave: relative to the
  // scene's extent, since float error in a hit point grows with its coordinates.
  float rayEpsilon() const { return ray_epsilon_; }
  // The bytes Embree's device holds for the scene (its memory monitor: the BVH, the vertex and
  // index buffers), for the raycast bench's table.
  std::size_t bytes() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  float ray_epsilon_ = 1e-4f;
};

// The scene::RayCaster the harness lends real-time techniques that trace rays on the CPU: an
// EmbreeScene built for the scene it is given.
scene::RayCasterFactory embreeRayCasterFactory();
// The same over a BVH already built (the raycast bench times and measures its EmbreeScene, then
// makes its rays through it).
std::unique_ptr<scene::RayCaster> embreeRayCaster(std::shared_ptr<const EmbreeScene> embree);

// The library version ("3.13.5"), recorded in outputs.
std::string embreeVersion();

}  // namespace gib::ref
