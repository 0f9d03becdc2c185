// The obscurance of book Ch. 10 (docs/rendering.md, "Obscurances"), written once for the
// reference's estimate (C++) and the obscurances technique (GLSL): the fall-off ρ(d) of eq. 10.2
// and the value one ray contributes to the estimate of eq. 10.6, scalar or spectral.
#pragma once

#ifdef __cplusplus
#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <cmath>

namespace gib::scene {
using glm::vec3;
using std::sqrt;
#ifndef GIB_SHARED_FUNCTION
#define GIB_SHARED_FUNCTION inline
#endif
#else
#ifndef GIB_SHARED_FUNCTION
#define GIB_SHARED_FUNCTION
#endif
#endif

// ρ(d) of eq. 10.2: kObscuranceFalloffSqrt is the book's √(d/d_max) below d_max and 1 beyond;
// kObscuranceFalloffStep is ambient occlusion's step, 0 below d_max and 1 beyond.
const int kObscuranceFalloffSqrt = 0;
const int kObscuranceFalloffStep = 1;

// ρ(d) for a hit at distance `d` ≥ 0 (a ray that hits nothing has d = ∞: ρ = 1).
GIB_SHARED_FUNCTION float obscuranceFalloff(int falloff, float d, float d_max) {
  if (d >= d_max) return 1.0f;
  return falloff == kObscuranceFalloffStep ? 0.0f : sqrt(d / d_max);
}

// The value one cosine-distributed ray contributes to eq. 10.6: ρ(d) in the scalar method; in
// the spectral one ρ(d)·a(y) for a hit y nearer than d_max (a: the albedo seen there) and the
// scene's average albedo ā for a ray that sees nothing that near (book §10.2).
GIB_SHARED_FUNCTION vec3 obscuranceSample(bool spectral, int falloff, float d, float d_max,
                                          vec3 hit_albedo, vec3 average_albedo) {
  float rho = obscuranceFalloff(falloff, d, d_max);
  if (!spectral) return vec3(rho);
  return d < d_max ? rho * hit_albedo : average_albedo;
}

#ifdef __cplusplus
}  // namespace gib::scene
#endif
