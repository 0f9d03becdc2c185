// The error terms of PRT that a figure separates (README.md, "Errors"), besides the transfer's
// Monte Carlo error (prt_transfer.h) and CPCA's (realtime/prt/cpca.h).
#pragma once

#include "scene/environment_map.h"

#include <glm/vec3.hpp>

#include <span>

namespace gib::rt::prt {

// The environment's own truncation to `bands` bands: Σ_texels Ω‖L − Σ_i L_i Y_i‖² /
// Σ_texels Ω‖L‖² over the map's texels (Ω each texel's solid angle, Y at its centre, the norm
// over RGB), with `coefficients` the map's exact projection (sh_projection.h), so that what
// remains is the truncation alone. 0 for a black map.
double shTruncationError(const scene::EnvironmentMap& map, std::span<const glm::vec3> coefficients,
                         int bands);

// Σ_v‖a_v − b_v‖² / Σ_v‖a_v‖² (0 when every a_v is zero): CPCA's error in the vertices'
// radiance under one lighting.
double relativeSquaredError(std::span<const glm::vec3> a, std::span<const glm::vec3> b);

}  // namespace gib::rt::prt
