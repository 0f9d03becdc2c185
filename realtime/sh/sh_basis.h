// Real spherical harmonics of any band up to order 8 (n bands hold n² functions), the directional
// basis of pre-computed radiance transfer (book §8.3; Sloan, Kautz & Snyder 2002). Same order
// and sign convention as the irradiance volume's bands 0–3 (spherical_harmonics.h), which now
// evaluates through this basis: coefficient index l·l + l + m for band l and −l ≤ m ≤ l, polar
// axis +z (cosθ = d.z, φ = atan2(d.y, d.x)),
//   Y_l^{m>0} = √2 K_l^m P_l^m(cosθ) cos(mφ),  Y_l^0 = K_l^0 P_l^0(cosθ),
//   Y_l^{m<0} = √2 K_l^|m| P_l^|m|(cosθ) sin(|m|φ),
// K_l^m = √((2l+1)/(4π) · (l−|m|)!/(l+|m|)!), and P_l^m without the Condon–Shortley phase
// (−1)^m (Sloan's convention: Y_1^{-1}, Y_1^0, Y_1^1 are positive multiples of y, z, x).
// realtime/sh/README.md states the book's misprints this corrects.
#pragma once

#include <glm/vec3.hpp>

#include <span>

namespace gib::rt::sh {

// The most bands evaluateShBasis serves: l = 0..7, 64 functions (PRT's "order 8").
inline constexpr int kShBasisMaxBands = 8;

// The functions of `bands` bands: n².
constexpr int shBasisCount(int bands) {
  return bands * bands;
}

// Throws gib::InputError unless 1 ≤ bands ≤ kShBasisMaxBands (bands may come from a parameter).
void checkShBands(int bands);

// Y_i(d) for i < bands², d a unit vector, into out[0, bands²) (out must hold that many; the
// rest is left alone). The associated Legendre recurrences of book §8.3 in x = cosθ, scaled by
// 1/sin^m θ so that the azimuthal factor sin^m θ·(cos mφ, sin mφ) = Re, Im (d.x + i d.y)^m is a
// polynomial too: no trigonometric call, no division, exact at the poles.
void evaluateShBasis(const glm::vec3& d, int bands, std::span<float> out);
void evaluateShBasis(const glm::dvec3& d, int bands, std::span<double> out);

}  // namespace gib::rt::sh
