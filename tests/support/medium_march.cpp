#include "support/medium_march.h"

namespace gib::test {

double marchedOpticalDepth(const scene::DensityGrid& medium, const glm::vec3& origin,
                           const glm::vec3& direction, double t0, double t1, int steps) {
  const double h = (t1 - t0) / steps;
  double depth = 0;
  for (int i = 0; i < steps; ++i)
    depth += h * medium.density(origin + float(t0 + (i + 0.5) * h) * direction);
  return depth;
}

}  // namespace gib::test
