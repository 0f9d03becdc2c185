#include "realtime/techniques/prt/prt_errors.h"

#include "realtime/sh/sh_basis.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <vector>

namespace gib::rt::prt {

double shTruncationError(const scene::EnvironmentMap& map, std::span<const glm::vec3> coefficients,
                         int bands) {
  const int n = sh::shBasisCount(bands);
  std::vector<float> basis(static_cast<std::size_t>(n));
  double error = 0, total = 0;
  const double pi = std::numbers::pi;
  for (int y = 0; y < map.height; ++y) {
    const double solid_angle =
        2.0 * pi / map.width *
        (std::cos(pi * y / map.height) - std::cos(pi * (y + 1) / map.height));
    for (int x = 0; x < map.width; ++x) {
      const glm::vec3 direction = map.toWorld(scene::latLongDirection(
          {(float(x) + 0.5f) / float(map.width), (float(y) + 0.5f) / float(map.height)}));
      sh::evaluateShBasis(direction, bands, basis);
      glm::dvec3 expansion(0.0);
      for (int i = 0; i < n; ++i)
        expansion += glm::dvec3(coefficients[std::size_t(i)]) * double(basis[std::size_t(i)]);
      const glm::dvec3 radiance = double(map.intensity) * glm::dvec3(map.texel(x, y));
      const glm::dvec3 difference = radiance - expansion;
      error += solid_angle * glm::dot(difference, difference);
      total += solid_angle * glm::dot(radiance, radiance);
    }
  }
  return total > 0 ? error / total : 0.0;
}

double relativeSquaredError(std::span<const glm::vec3> a, std::span<const glm::vec3> b) {
  double error = 0, total = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const glm::dvec3 difference = glm::dvec3(a[i]) - glm::dvec3(b[i]);
    error += glm::dot(difference, difference);
    total += glm::dot(glm::dvec3(a[i]), glm::dvec3(a[i]));
  }
  return total > 0 ? error / total : 0.0;
}

}  // namespace gib::rt::prt
