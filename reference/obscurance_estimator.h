// The reference's estimate of the obscurance W(x) of book Ch. 10 (docs/rendering.md,
// "Obscurances"): cosine-distributed rays from x traced with Embree to their closest hit, each
// contributing ρ(d) (scalar) or ρ(d)·a(y), else the scene's average albedo (spectral), the value
// eq. 10.6 averages. The exact quantity the obscurances technique approximates with global ray
// bundles; the progressive renderer renders it per pixel (RenderSettings::obscurance).
#pragma once

#include "reference/embree_scene.h"
#include "reference/triangle_table.h"
#include "scene/obscurance.h"
#include "scene/scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace gib::ref {

class ObscuranceEstimator {
 public:
  // Builds its own BVH and triangle table for `scene`, which must outlive it.
  ObscuranceEstimator(const scene::Scene& scene, const scene::ObscuranceDefinition& definition);
  // Borrows a path tracer's (PathTracer::embree(), triangles()), which must outlive it.
  ObscuranceEstimator(const scene::Scene& scene, const scene::ObscuranceDefinition& definition,
                      const EmbreeScene& embree, const TriangleTable& triangles);
  ~ObscuranceEstimator();

  // One ray's value: a cosine-distributed direction about `normal` (unit, on the side the
  // obscurance is of) from the uniform point `u`, traced from `point` offset along the normal as
  // the path tracer offsets its rays; d is the distance from `point` to the closest hit (∞ for a
  // miss). Its expectation is W(point) (eq. 10.2 or 10.4). The medium, if any, is ignored: the
  // obscurance is of surfaces.
  glm::vec3 sample(const glm::vec3& point, const glm::vec3& normal, glm::vec2 u) const;

  const scene::ObscuranceDefinition& definition() const { return definition_; }
  float maxDistance() const { return d_max_; }                         // scene units
  const scene::Rgb& averageAlbedo() const { return average_albedo_; }  // ā, the spectral miss
  const EmbreeScene& embree() const { return *embree_; }
  const TriangleTable& triangles() const { return *triangles_; }

 private:
  const scene::Scene& scene_;
  scene::ObscuranceDefinition definition_;
  std::unique_ptr<EmbreeScene> owned_embree_;
  std::unique_ptr<TriangleTable> owned_triangles_;
  const EmbreeScene* embree_;
  const TriangleTable* triangles_;
  float d_max_;
  scene::Rgb average_albedo_;
};

// A point whose obscurance is estimated: a position on a surface and the unit normal of the side
// it is of.
struct ObscurancePoint {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
};

// W at one point from `rays` independent rays: their mean and its standard error s/√M, which
// has M − 1 degrees of freedom (a Student's t statistic).
struct ObscuranceEstimate {
  glm::dvec3 mean{0.0};
  glm::dvec3 standard_error{0.0};
  std::uint32_t rays = 0;
};

// Estimates W at every point with `rays` ≥ 2 rays each. Ray j of point i draws its direction from
// its own independent scramble of (seed, i, j) (the path sampler with one replica per ray), so the
// rays are independent, their spread is an honest standard error, and the estimates do not depend
// on `threads` (0: every core).
std::vector<ObscuranceEstimate> estimateObscurances(const ObscuranceEstimator& estimator,
                                                    std::span<const ObscurancePoint> points,
                                                    std::uint32_t rays, std::uint64_t seed,
                                                    int threads = 0);

}  // namespace gib::ref
