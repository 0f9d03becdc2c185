#include "reference/medium_tracking.h"

#include <cmath>
#include <limits>

namespace gib::ref {

namespace {

// Optical thickness to the next tentative collision: an exponential variate of mean 1.
float sampleOpticalThickness(WalkRandom& random) {
  return -std::log1p(-random.next());
}

}  // namespace

template <typename OnTentativeCollision>
void MediumTracker::trackTentativeCollisions(const glm::vec3& origin, const glm::vec3& direction,
                                             float t_max, WalkRandom& random,
                                             OnTentativeCollision&& on_collision) const {
  float remaining = sampleOpticalThickness(random);
  walkMajorants(origin, direction, t_max, [&](float t0, float t1, float majorant) {
    if (majorant <= 0) return true;
    float t = t0;
    for (;;) {
      // The exponential is memoryless, so the thickness left over at a segment's end carries
      // into the next segment with its own majorant.
      const float thickness = majorant * (t1 - t);
      if (remaining >= thickness) {
        remaining -= thickness;
        return true;
      }
      t += remaining / majorant;
      if (!on_collision(t, grid_.density(origin + t * direction) / majorant)) return false;
      remaining = sampleOpticalThickness(random);
    }
  });
}

float MediumTracker::sampleCollision(const glm::vec3& origin, const glm::vec3& direction,
                                     float t_max, WalkRandom random) const {
  float collision = std::numeric_limits<float>::infinity();
  trackTentativeCollisions(origin, direction, t_max, random, [&](float t, float real_fraction) {
    // A tentative collision is real with probability σt/majorant, else null: go on.
    if (random.next() >= real_fraction) return true;
    collision = t;
    return false;
  });
  return collision;
}

float MediumTracker::transmittance(const glm::vec3& origin, const glm::vec3& direction, float t_max,
                                   WalkRandom random) const {
  // Below this estimate, Russian roulette decides whether the walk goes on.
  constexpr float kRouletteThreshold = 0.1f;
  float estimate = 1.0f;
  trackTentativeCollisions(origin, direction, t_max, random, [&](float, float real_fraction) {
    estimate *= 1.0f - real_fraction;
    if (estimate < kRouletteThreshold) {
      const float survive = estimate / kRouletteThreshold;
      if (random.next() >= survive) {
        estimate = 0.0f;
        return false;
      }
      estimate = kRouletteThreshold;  // = estimate / survive
    }
    return true;
  });
  return estimate;
}

}  // namespace gib::ref
