// Rays and the agreement of two casts, for the tests of the GPU ray-casting structures
// (realtime/ray_casting/): seeded rays from uniform points of a scene's bounds in uniform
// directions, and the rule two casts of one triangle test agree by.
#pragma once

#include "realtime/ray_casting/ray_cast_pass.h"

#include <cstdint>
#include <string>
#include <vector>

namespace gib::test {

// A uniform number in [0, 1) from a SplitMix64 state, which it advances.
double unitUniform(std::uint64_t& state);

// `count` rays in the set's coordinates from uniform points of its bounds, uniform directions.
std::vector<rt::CastRay> randomCastRays(const rt::IvmTriangleSet& set, int count,
                                        std::uint64_t seed);

// Two casts agree when they name the same triangle (or both miss), or when both hit and their t
// differ by at most `tie`: two triangles meeting where the ray crosses (a shared edge, a corner)
// tie within the triangle test's rounding, and which one a traversal meets first decides. Stricter
// than the comparison with Embree (hit_comparison.h): a hit against a miss is never a tie here,
// since both casts run the same triangle test.
bool sameCastHit(const rt::gpu::RayCastHit& a, const rt::gpu::RayCastHit& b, float tie);

// "ray o=(…) d=(…): triangle N t=T", for failure messages.
std::string describeCast(const rt::CastRay& ray, const rt::gpu::RayCastHit& hit);

}  // namespace gib::test
