// Importance sampling of an environment map (scene/environment_map.h): directions drawn with a
// density proportional to the luminance of their texel, in solid angle. The distribution is
// piecewise constant over the texels in (u, v) = (φ/2π, θ/π), each texel weighted by its
// luminance times sin θ at its row's centre (pbrt-v4's image infinite light does the same), and
// the density of a direction in solid angle is p(u, v) / (2π² sin θ). A texel with radiance in
// any channel has luminance > 0 (every Rec.709 weight is positive), so the density is positive
// wherever the map is not black, as multiple importance sampling needs. Shared by the reference's
// next-event estimation and the real-time techniques' light samples. Deterministic.
#pragma once

#include "scene/environment_map.h"

#include <span>
#include <vector>

namespace gib::scene {

struct EnvironmentSample {
  glm::vec3 direction{0.0f};  // world direction towards the environment, unit
  float pdf = 0.0f;           // density in solid angle; 0 when nothing could be drawn
  Rgb radiance{0.0f};         // L(direction), intensity included
};

class EnvironmentDistribution {
 public:
  explicit EnvironmentDistribution(const EnvironmentMap& map);

  // A direction from two uniform numbers in [0, 1): u.x chooses the row, u.y the column.
  EnvironmentSample sample(glm::vec2 u) const;
  // The density in solid angle of drawing the world direction (any length > 0).
  float pdf(const glm::vec3& world_direction) const;
  // Whether the map is black: then sample() gives pdf 0 and no light.
  bool black() const { return total_ <= 0.0; }

 private:
  // Finds the interval of `cdf` (non-decreasing, cdf[0] = 0, n + 1 entries) containing u·total.
  static int findInterval(std::span<const double> cdf, double target);
  float texelDensity(int x, int y) const;  // p(u, v) of the texel

  EnvironmentMap map_;              // shares the texels
  std::vector<double> row_cdf_;     // height + 1: the marginal over rows
  std::vector<double> column_cdf_;  // height × (width + 1): each row's conditional
  double total_ = 0.0;
};

}  // namespace gib::scene
