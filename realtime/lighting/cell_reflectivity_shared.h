// The integrated reflectivity of environment_shadows (book §4.2.3, eq. for a(Δω_i, ω), after
// Barsi, Szirmay-Kalos & Szécsi 2005, the book's [10]) as C++ and GLSL both read it: a cell of
// the environment is taken as a spherical cap of its solid angle around its centre, and the
// BRDF × cos⁺ averaged over the cap is read from tables of the mean of cos⁺^s over a cap of
// half-angle α whose axis lies at angle β from the lobe's axis. A directional light sample
// carries its cap's half-angle α in GpuLightSample::position.w (light_sample_shared.h).
#pragma once
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
#include <glm/exponential.hpp>

namespace gib::rt::gpu {
using glm::sqrt;
#endif

// The tables, a 2D array: layer 0 s = 1 (the clamped cosine, the diffuse term), layer 1 + k the
// scene's k-th Phong exponent. Bound by the technique that sets the shading passes'
// GIB_CELL_REFLECTIVITY define, in its own units.
const int kCellReflectivityUnit = kTechniqueFirstUnit + 0;
// Texels a side. Both axes go as the square root of the angle over π (texel i at angle
// π·(i/(N−1))²), so small caps and the narrow lobes near β = 0 get fine steps: with 64, the
// step at β = 0.1 rad is 0.017 rad, a seventh of the width of a cos¹⁰⁰ lobe.
const int kCellReflectivitySize = 64;
// Distinct Phong exponents a scene may use, one table each.
const int kMaxCellReflectivityExponents = 8;

// Texture coordinates of (α, β), radians in [0, π]: texel centres at the grid's angles.
GIB_SHARED_FUNCTION vec2 cellReflectivityCoordinates(float alpha, float beta) {
  const float n = float(kCellReflectivitySize);
  vec2 root = vec2(sqrt(alpha * 0.31830988618379067f), sqrt(beta * 0.31830988618379067f));
  return (root * (n - 1.0f) + vec2(0.5f)) / n;
}

#ifdef __cplusplus
static_assert(kCellReflectivityUnit < kTechniqueFirstUnit + kTechniqueUnitCount,
              "the reflectivity tables stay inside the technique's units");
}  // namespace gib::rt::gpu
#endif
