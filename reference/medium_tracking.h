// Unbiased free-flight sampling and transmittance estimation in the heterogeneous medium of
// scene/medium.h: delta (Woodcock) tracking and ratio tracking against a piecewise-constant
// majorant read from the density grid's cells along the ray (3D-DDA).
#pragma once

#include "reference/rng.h"
#include "scene/medium.h"

#include <glm/vec3.hpp>

namespace gib::ref {

// The random numbers of one tracking walk, whose count is not known in advance: the first from
// the path's sampler (a low-discrepancy dimension of its own), the rest from an independent
// stream. Made from a stream alone, every number comes from the stream.
class WalkRandom {
 public:
  WalkRandom(float first, SampleStream& rest) : first_(first), rest_(&rest), has_first_(true) {}
  WalkRandom(SampleStream& stream) : rest_(&stream) {}  // NOLINT: a stream is a walk's randomness
  float next() {
    if (!has_first_) return rest_->next();
    has_first_ = false;
    return first_;
  }

 private:
  float first_ = 0;
  SampleStream* rest_;
  bool has_first_ = false;
};

class MediumTracker {
 public:
  explicit MediumTracker(const scene::DensityGrid& grid) : grid_(grid) {}

  // Delta tracking along origin + t·direction (direction unit), t in (0, t_max): the distance of
  // the first real collision, sampled with density σt(t)·T(t), or +infinity when the ray leaves
  // the segment first (with probability T(t_max)).
  float sampleCollision(const glm::vec3& origin, const glm::vec3& direction, float t_max,
                        WalkRandom random) const;

  // Ratio tracking: an unbiased estimate of T = exp(−∫σt) over (0, t_max), in [0, 1]. Russian
  // roulette ends walks whose estimate has become small, without bias.
  float transmittance(const glm::vec3& origin, const glm::vec3& direction, float t_max,
                      WalkRandom random) const;

  // Calls visit(t0, t1, majorant) for consecutive segments of (0, t_max) inside the grid, in
  // order, until it returns false. Segments outside the grid have zero density and are skipped.
  template <typename Visit>
  void walkMajorants(const glm::vec3& origin, const glm::vec3& direction, float t_max,
                     Visit&& visit) const;

  const scene::DensityGrid& grid() const { return grid_; }

 private:
  // Tentative collisions of the majorant's exponential flight along the segment, in order:
  // on_collision(t, σt/majorant) returns false to stop.
  template <typename OnTentativeCollision>
  void trackTentativeCollisions(const glm::vec3& origin, const glm::vec3& direction, float t_max,
                                WalkRandom& random, OnTentativeCollision&& on_collision) const;

  const scene::DensityGrid& grid_;
};

}  // namespace gib::ref

#include "reference/medium_tracking_walk.h"
