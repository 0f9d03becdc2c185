#include "reference/phase_function.h"

#include "reference/sampling.h"

#include <algorithm>
#include <cmath>

namespace gib::ref {

float henyeyGreenstein(float cos_theta, float g) {
  const float denominator = 1.0f + g * g - 2.0f * g * cos_theta;
  return (1.0f - g * g) / (4.0f * kPi * denominator * std::sqrt(denominator));
}

glm::vec3 sampleHenyeyGreenstein(const glm::vec3& direction, float g, glm::vec2 u) {
  // Inverting the CDF of cos θ; near g = 0 the closed form loses precision, and the
  // distribution is uniform there anyway.
  float cos_theta;
  if (std::abs(g) < 1e-3f) {
    cos_theta = 1.0f - 2.0f * u.x;
  } else {
    const float s = (1.0f - g * g) / (1.0f - g + 2.0f * g * u.x);
    cos_theta = (1.0f + g * g - s * s) / (2.0f * g);
  }
  cos_theta = std::clamp(cos_theta, -1.0f, 1.0f);
  const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
  const float phi = 2.0f * kPi * u.y;
  return Frame(direction).toWorld(
      {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta});
}

}  // namespace gib::ref
