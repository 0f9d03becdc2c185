// The Fresnel function of book §1.1 (docs/rendering.md, "Mirrors and glass"), written once for
// the reference (C++) and the real-time techniques (GLSL, through the shader library's includes):
// the exact unpolarised reflectance of a smooth interface, eq. 1.5, for a dielectric and for a
// conductor, and the approximation of eq. 1.6 that real-time shaders use. Per channel: a vec3 of
// indices gives a vec3 of reflectances. The outside medium has index 1 (air).
#pragma once

#ifdef __cplusplus
#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/vec3.hpp>

#include <cmath>

namespace gib::scene {
using glm::max;
using glm::sqrt;
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

// Eq. 1.5 for a dielectric (κ = 0): the reflectance of light arriving at angle θ' with
// cos θ' = `cos_i` ≥ 0 on the side of relative index `eta` (the index behind the interface over
// the index in front: ior from outside, 1/ior from inside). 1 beyond the critical angle (total
// internal reflection). The s and p amplitudes are (cos θ' − η cos θ)/(cos θ' + η cos θ) and
// (η cos θ' − cos θ)/(η cos θ' + cos θ), θ the refraction angle.
GIB_SHARED_FUNCTION float fresnelDielectric(float cos_i, float eta) {
  float sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.0f) return 1.0f;
  float cos_t = sqrt(1.0f - sin2_t);
  float rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  float rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return 0.5f * (rs * rs + rp * rp);
}

// Eq. 1.5 for a conductor of complex index n + iκ, light arriving from air at cos θ' = `cos_i`,
// in closed real form: with s = |η² − sin²θ'| = √((n² − κ² − sin²θ')² + 4n²κ²) and
// a = √((s + n² − κ² − sin²θ')/2) (the real part of √(η² − sin²θ')),
// R⊥ = (s + cos²θ' − 2a cos θ')/(s + cos²θ' + 2a cos θ') and
// R∥ = R⊥ · (s cos²θ' + sin⁴θ' − 2a cos θ' sin²θ')/(s cos²θ' + sin⁴θ' + 2a cos θ' sin²θ')
// (Born & Wolf, Principles of Optics, §14.2). κ = 0 gives fresnelDielectric.
GIB_SHARED_FUNCTION vec3 fresnelConductor(float cos_i, vec3 n, vec3 k) {
  float c2 = cos_i * cos_i;
  float s2 = 1.0f - c2;
  vec3 t0 = n * n - k * k - vec3(s2);
  vec3 s = sqrt(t0 * t0 + 4.0f * n * n * k * k);
  vec3 a = sqrt(max(vec3(0.0f), 0.5f * (s + t0)));
  vec3 t1 = s + vec3(c2);
  vec3 t2 = 2.0f * cos_i * a;
  vec3 r_s = (t1 - t2) / (t1 + t2);
  vec3 t3 = c2 * s + vec3(s2 * s2);
  vec3 t4 = t2 * s2;
  vec3 r_p = r_s * (t3 - t4) / (t3 + t4);
  return 0.5f * (r_s + r_p);
}

// Eq. 1.6: the reflectance at perpendicular incidence, F⊥ = ((n − 1)² + κ²)/((n + 1)² + κ²),
// exact (it is eq. 1.5 at θ' = 0).
GIB_SHARED_FUNCTION vec3 fresnelAtNormalIncidence(vec3 n, vec3 k) {
  return ((n - vec3(1.0f)) * (n - vec3(1.0f)) + k * k) /
         ((n + vec3(1.0f)) * (n + vec3(1.0f)) + k * k);
}

// The approximation the book's shaders use with F⊥ (eq. 1.6 and the line above it):
// F(θ') ≈ F⊥ + (1 − F⊥)(1 − cos θ')⁵ (Schlick).
GIB_SHARED_FUNCTION vec3 fresnelApproximation(vec3 f_perpendicular, float cos_i) {
  float m = 1.0f - cos_i;
  float m2 = m * m;
  return f_perpendicular + (vec3(1.0f) - f_perpendicular) * (m2 * m2 * m);
}

#ifdef __cplusplus
}  // namespace gib::scene
#endif
