// The reference integrator: unidirectional path tracing with next-event estimation to every light
// type, combined with BSDF sampling by multiple importance sampling (power heuristic), and
// unbiased Russian roulette. It can restrict itself to a path class (DESIGN.md, "Path classes").
#pragma once

#include "reference/area_light_sampler.h"
#include "reference/embree_scene.h"
#include "reference/rng.h"
#include "reference/triangle_table.h"
#include "scene/scene.h"

#include <cstdint>
#include <limits>

namespace gib::ref {

// Bounces are the scattering vertices between the light and the eye: an emitter seen directly
// has 0 bounces, direct lighting (L D E) has 1. Only paths with min ≤ bounces ≤ max contribute.
struct PathClass {
  static constexpr int kUnlimited = std::numeric_limits<int>::max();
  int min_bounces = 0;
  int max_bounces = kUnlimited;

  bool contains(int bounces) const { return bounces >= min_bounces && bounces <= max_bounces; }
};

struct RadianceSample {
  scene::Rgb total{0.0f};
  scene::Rgb direct{0.0f};  // the part carried by paths of at most one bounce (L E and L D E)
  std::uint32_t rays = 0;   // intersection and shadow rays traced
};

class PathTracer {
 public:
  // Russian roulette starts after this many bounces: early vertices carry most of the image.
  static constexpr int kRouletteStartBounce = 3;

  PathTracer(const scene::Scene& scene, PathClass path_class);

  RadianceSample radiance(const glm::vec3& origin, const glm::vec3& direction,
                          SampleStream& random) const;

  const EmbreeScene& embree() const { return embree_; }
  const PathClass& pathClass() const { return path_class_; }

 private:
  struct Vertex;
  // Next-event estimation at a scattering vertex: one sample of the area lights, one of the sky,
  // and every spot and directional light (delta lights, so no MIS).
  scene::Rgb estimateDirect(const Vertex& v, SampleStream& random, std::uint32_t& rays) const;

  bool segmentIsClear(const glm::vec3& origin, const glm::vec3& target) const;

  const scene::Scene& scene_;
  PathClass path_class_;
  EmbreeScene embree_;
  TriangleTable triangles_;
  AreaLightSampler area_lights_;
  bool has_sky_;
};

}  // namespace gib::ref
