// The global ray bundles of the obscurances technique (book §10.4): their directions and the
// shifts of their pixel grids.
//
// Why these directions: the bundle estimate (obscurances_technique.h) is unbiased when every
// direction is, on its own, uniform over the sphere and every grid shift uniform over a pixel.
// A fixed point set turned by one uniformly random rotation has that property whatever the set,
// so the set can be chosen for low variance: the 2D Sobol (0,2)-sequence mapped to the hemisphere
// by equal areas (z uniform, φ uniform), whose every prefix is stratified, so that the first n
// bundles of a run of N cover the directions as evenly as a run of n. A line and its reverse are
// the same line, so one hemisphere of directions is enough: a bundle serves the surfaces facing
// either way along it.
#pragma once

#include "realtime/depth_peeling/depth_peeler.h"

#include <cstdint>
#include <vector>

namespace gib::rt::obscurance {

// `count` bundles of the seeded random rotation and grid shifts: the same for the same seed.
std::vector<PeelBundle> bundleSet(int count, std::uint32_t seed);

}  // namespace gib::rt::obscurance
