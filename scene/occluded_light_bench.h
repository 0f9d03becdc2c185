// The geometry of Fournier & Péroche's bench test of area-light sampling (§6.1): a square light
// partly hidden by a square occluder above a receiving plane. Shared by the exact solution's
// tests and benchmark and by the GPU sampler's measurement (`gibench solid-angle-bench`).
#pragma once

#include <glm/vec3.hpp>

#include <vector>

namespace gib::scene {

// A 1×1 light facing down at height 2 above the origin; a 0.6×0.6 occluder at height 1, centred
// at (0.25, 1, 0.15), its edges parallel to the light's (so aligned with a sampling grid laid on
// the light); the receiving plane y = 0 over [−2, 2]², sampled at the centres of a grid × grid
// lattice (100 × 100: the paper's 10 000 points).
struct OccludedLightBench {
  std::vector<glm::dvec3> light;     // its corners, in order (normal −y)
  std::vector<glm::dvec3> occluder;  // its corners, in order
  double plane_half_extent = 2.0;
  int grid = 100;
};
OccludedLightBench occludedLightBench(int grid = 100);

// The receiver points, row by row along z, then along x.
std::vector<glm::dvec3> occludedLightBenchPoints(const OccludedLightBench& bench);

}  // namespace gib::scene
