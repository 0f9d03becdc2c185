#include "scene/occluded_light_bench.h"

namespace gib::scene {

OccludedLightBench occludedLightBench(int grid) {
  OccludedLightBench b;
  b.grid = grid;
  b.light = {{-0.5, 2, -0.5}, {0.5, 2, -0.5}, {0.5, 2, 0.5}, {-0.5, 2, 0.5}};
  const glm::dvec3 centre(0.25, 1, 0.15);
  const double h = 0.3;
  b.occluder = {centre + glm::dvec3(-h, 0, -h), centre + glm::dvec3(h, 0, -h),
                centre + glm::dvec3(h, 0, h), centre + glm::dvec3(-h, 0, h)};
  return b;
}

std::vector<glm::dvec3> occludedLightBenchPoints(const OccludedLightBench& b) {
  std::vector<glm::dvec3> points;
  const double cell = 2 * b.plane_half_extent / b.grid;
  for (int j = 0; j < b.grid; ++j)
    for (int i = 0; i < b.grid; ++i)
      points.emplace_back(-b.plane_half_extent + (i + 0.5) * cell, 0.0,
                          -b.plane_half_extent + (j + 0.5) * cell);
  return points;
}

}  // namespace gib::scene
