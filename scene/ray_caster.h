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
#include <span>

namespace gib::scene {

struct RayHit {
  float t = std::numeric_limits<float>::infinity();
  std::uint32_t mesh = 0;      // index into Scene::meshes
  std::uint32_t triangle = 0;  // index into that mesh's triangles
  bool valid() const { return t < std::numeric_limits<float>::infinity(); }
};

// One ray of a batch: origin + t·direction for t in (t_near, t_far).
struct Ray {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, 1.0f};
  float t_near = 0.0f;
  float t_far = std::numeric_limits<float>::infinity();
};

class RayCaster {
 public:
  virtual ~RayCaster() = default;
  // Closest hit along origin + t·direction for t in (t_near, ∞); `direction` need not be unit.
  virtual RayHit intersect(const glm::vec3& origin, const glm::vec3& direction,
                           float t_near) const = 0;
  // The closest hit of every ray of a batch (hits.size() == rays.size()). `coherent`: the rays
  // share an origin or a direction (a hemisphere's rays), which an implementation may trace
  // together. This one traces them one at a time.
  virtual void intersect(std::span<const Ray> rays, std::span<RayHit> hits,
                         bool coherent = false) const;
  // Whether anything lies on each ray's segment (blocked.size() == rays.size()).
  virtual void occluded(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const;
  // An offset for spawned rays that keeps them off the surface they leave.
  virtual float rayEpsilon() const = 0;
};

// Builds a caster for a scene (the BVH build is part of the caller's timing).
using RayCasterFactory = std::function<std::unique_ptr<RayCaster>(const Scene&)>;

}  // namespace gib::scene
