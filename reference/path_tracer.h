// The reference integrator: unidirectional path tracing with next-event estimation to every light
// type, combined with BSDF (or phase-function) sampling by multiple importance sampling (power
// heuristic), unbiased Russian roulette, and a heterogeneous medium integrated by delta tracking
// (free paths) and ratio tracking (shadow rays). Mirrors and glass are followed by sampling their
// one or two directions. It can restrict itself to a path class (docs/rendering.md, "Path
// classes"), and leave to the light tracer (reference/light_tracer.h) the paths that reach a
// diffuse surface seen by the eye from a specular one next to the light (docs/rendering.md,
// "Caustics: light tracing").
#pragma once

#include "reference/area_light_sampler.h"
#include "reference/embree_scene.h"
#include "reference/medium_tracking.h"
#include "reference/path_sampler.h"
#include "reference/scattering_vertex.h"
#include "reference/triangle_table.h"
#include "scene/environment_distribution.h"
#include "scene/medium.h"
#include "scene/path_class.h"
#include "scene/path_expression.h"
#include "scene/scene.h"

#include <cstdint>
#include <limits>
#include <optional>

namespace gib::ref {

using PathClass = scene::PathClass;

struct RadianceSample {
  scene::Rgb total{0.0f};
  scene::Rgb direct{0.0f};  // the part carried by paths of at most one bounce
  std::uint32_t rays = 0;   // intersection and shadow rays traced
};

class PathTracer {
 public:
  // Russian roulette starts after this many bounces: early vertices carry most of the image.
  static constexpr int kRouletteStartBounce = 3;
  // A path that keeps its full throughput (albedo 1 everywhere, no way out) would never end: it
  // is cut here. Any scene that absorbs or lets light escape loses all but a vanishing share of
  // its paths long before (a lossless cloud of optical depth 10 scatters ~100 times).
  static constexpr int kMaxBounceGuard = 100000;

  // With `light_paths`, paths whose vertex next to the light is specular and whose vertex seen by
  // the eye is diffuse (L S (D|S)* D E) are the light tracer's, and this tracer leaves them out;
  // the two images add up to every path once.
  // `environment_occlusion` false: the environment's light is never blocked (RenderSettings).
  PathTracer(const scene::Scene& scene, PathClass path_class, bool light_paths = false,
             bool environment_occlusion = true);

  // The radiance arriving at `origin` from `direction`. `first_hit`, when given, is the closest
  // hit of that ray, already traced by the caller (camera rays go to Embree in coherent batches).
  RadianceSample radiance(const glm::vec3& origin, const glm::vec3& direction, PathSampler& sampler,
                          const Hit* first_hit = nullptr) const;

  const EmbreeScene& embree() const { return embree_; }
  const TriangleTable& triangles() const { return triangles_; }
  const AreaLightSampler& areaLights() const { return area_lights_; }
  const PathClass& pathClass() const { return path_class_; }
  const scene::PathExpression& pathExpression() const { return expression_; }
  bool leavesLightPaths() const { return light_paths_; }
  // Null when the scene has no medium.
  const MediumTracker* medium() const { return medium_ ? &*medium_ : nullptr; }

 private:
  // Next-event estimation at a scattering vertex: one sample of the area lights, one of the sky,
  // and every spot and directional light (delta lights, so no MIS).
  scene::Rgb estimateDirect(const ScatteringVertex& v, PathSampler& sampler,
                            std::uint32_t& rays) const;
  // Fraction of light arriving at `target` from `origin`: 0 when a surface blocks the segment,
  // else the medium's transmittance (1 without a medium).
  float segmentTransmittance(const glm::vec3& origin, const glm::vec3& target, WalkRandom random,
                             std::uint32_t& rays) const;
  // The same for a ray to infinity.
  float rayTransmittance(const glm::vec3& origin, const glm::vec3& direction, WalkRandom random,
                         std::uint32_t& rays) const;
  // Of a ray towards the environment: rayTransmittance, or 1 without the environment's occlusion
  // (then neither shadow ray nor tracking walk is drawn).
  float environmentTransmittance(const glm::vec3& origin, const glm::vec3& wi, PathSampler& sampler,
                                 std::uint32_t& rays) const;
  // The MIS weight of environment light drawn by the light's strategy: the power heuristic against
  // BSDF or phase sampling, or 1 without the environment's occlusion (paths that leave the scene
  // after a diffuse or glossy vertex then add none).
  float environmentLightWeight(float pdf_light, float pdf_scattering) const;

  const scene::Scene& scene_;
  PathClass path_class_;
  scene::PathExpression expression_;
  bool light_paths_;
  EmbreeScene embree_;
  TriangleTable triangles_;
  AreaLightSampler area_lights_;
  scene::DensityGrid density_;
  std::optional<MediumTracker> medium_;
  bool has_sky_;
  bool environment_occlusion_;
  // The environment map's importance distribution, when the scene has a map.
  std::optional<scene::EnvironmentDistribution> environment_;
};

}  // namespace gib::ref
