// A CPU ray caster over a scene's triangles, as an interface: the real-time layer may not include
// the reference layer (docs/architecture.md, "Layers"), yet a technique whose preprocessing
// traces rays on the CPU (light path maps, book §8.4: "CPU ray casting") needs one. The harness
// lends it the reference's Embree BVH through this interface (realtime/technique.h,
// TechniqueServices); tests may lend any implementation.
#pragma once

#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>

namespace gib::scene {

struct RayHit {
  float t = std::numeric_limits<float>::infinity();
  std::uint32_t mesh = 0;      // index into Scene::meshes
  std::uint32_t triangle = 0;  // index into that mesh's triangles
  bool valid() const { return t < std::numeric_limits<float>::infinity(); }
};

class RayCaster {
 public:
  virtual ~RayCaster() = default;
  // Closest hit along origin + t·direction for t in (t_near, ∞); `direction` need not be unit.
  virtual RayHit intersect(const glm::vec3& origin, const glm::vec3& direction,
                           float t_near) const = 0;
  // An offset for spawned rays that keeps them off the surface they leave.
  virtual float rayEpsilon() const = 0;
};

// Builds a caster for a scene (the BVH build is part of the caller's timing).
using RayCasterFactory = std::function<std::unique_ptr<RayCaster>(const Scene&)>;

}  // namespace gib::scene
