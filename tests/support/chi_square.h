// Chi-square goodness-of-fit of a direction sampler against its density (pbrt-v4's approach):
// bin 10⁶ samples on the sphere in (cos θ, φ), integrate the density over each bin numerically,
// pool bins with an expected count below 5, and return the p-value.
#pragma once

#include "reference/rng.h"

#include <glm/vec3.hpp>

#include <functional>
#include <vector>

namespace gib::test {

using DirectionSampler = std::function<glm::vec3(ref::SampleStream&)>;
using DirectionPdf = std::function<double(const glm::vec3&)>;

inline constexpr int kChiSquareSamples = 1000000;

// The density must integrate to one over the sphere (checked with EXPECT_NEAR to 1e-3).
double chiSquarePValue(const DirectionSampler& sample, const DirectionPdf& pdf);

// The p-value of observed counts against expected counts (same total) over discrete cells,
// cells expected below 5 pooled into one.
double chiSquarePValue(const std::vector<double>& observed, const std::vector<double>& expected);

}  // namespace gib::test
