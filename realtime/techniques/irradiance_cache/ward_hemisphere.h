// A record's hemisphere sampled as Ward & Heckbert (1992) do: M × N strata, uniform in sin²θ and
// φ (cosine-weighted), one jittered ray each; E = π/(MN) Σ L, the harmonic mean distance, and the
// rotation and translation gradients from the strata (the boundaries between neighbouring strata
// move with the nearer of their two surfaces). The CPU irradiance cache's records.
#pragma once

#include "realtime/irradiance_cache/irradiance_cache_shared.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <limits>
#include <span>

namespace gib::rt {

struct WardStrata {
  int theta = 1;  // M
  int phi = 1;    // N
  int count() const { return theta * phi; }
};

// About `rays` strata with N ≈ πM (Ward's proportion: strata about square on the hemisphere).
WardStrata wardStrata(int rays);

// The direction of stratum (j, k) (θ ring j, φ sector k) at the jitter u ∈ [0,1)², in the frame
// (t, b, n).
glm::vec3 wardDirection(const glm::vec3& t, const glm::vec3& b, const glm::vec3& n, int j, int k,
                        const WardStrata& strata, const glm::vec2& u);

// What a stratum's ray brought back: the radiance, and the distance to the surface it met
// (infinite where none).
struct HemisphereSample {
  glm::vec3 radiance{0.0f};
  float distance = std::numeric_limits<float>::infinity();
};

// The record at p with unit normal n from samples[j·N + k] of the strata (frame: basisTangent and
// basisBitangent of n). R is the unclamped harmonic mean distance (infinite when no ray met a
// surface).
gpu::IrradianceRecord wardRecord(const glm::vec3& p, const glm::vec3& n, const WardStrata& strata,
                                 std::span<const HemisphereSample> samples);

}  // namespace gib::rt
