// Real spherical harmonics up to band 3 and what the irradiance volume (Nijasure et al. 2005)
// needs of them on the CPU: the basis, the per-texel weights Y·dω of cube-map faces (their
// eq. 2), and the zonal transfer factors of eq. 4 for Lambert (eq. 6) and normalised Phong
// (eq. 5) lobes. GL-free, so the tests check it against analytic integrals; the shaders evaluate
// the same basis (spherical_harmonics.glsl, same constants and order).
//
// Coefficient order: index l·l + l + m for band l and −l ≤ m ≤ l, the real basis
// Y_l^{m>0} = √2 N cos(mφ) P_l^m, Y_l^0 = N P_l^0, Y_l^{m<0} = √2 N sin(|m|φ) P_l^{|m|}, without
// the Condon–Shortley phase (Sloan's convention; the paper's complex Y_l^m span the same space).
#pragma once

#include "realtime/sh/spherical_harmonics_shared.h"

#include <glm/vec3.hpp>

#include <array>
#include <functional>
#include <vector>

namespace gib::rt::sh {

// The expansion's size is shared with the shaders (spherical_harmonics_shared.h).
using gpu::kShMaxBand;
using gpu::kShMaxCoefficients;
using gpu::shCoefficientCount;

// Y_i(d) for i < kShMaxCoefficients, d a unit vector: the general basis (sh_basis.h) cut to
// bands 0..3.
std::array<float, kShMaxCoefficients> evaluateBasis(const glm::vec3& d);

// Cube-map conventions of OpenGL (faces +x, −x, +y, −y, +z, −z; texel (i, j) with i along s and
// j along t): the unit direction through the centre of a texel, and the texel's exact solid
// angle (the area of its square on the unit cube projected to the sphere).
glm::vec3 cubeTexelDirection(int face, int i, int j, int size);
double cubeTexelSolidAngle(int i, int j, int size);

// Eq. 2's weights Y_c(ω)·A(ω) of every texel: index ((face·size + j)·size + i)·count + c.
std::vector<float> cubeProjectionWeights(int size, int band);

// The coefficients of a function on the sphere by eq. 2 over cube faces of `size` texels.
std::vector<double> projectOnCube(const std::function<glm::dvec3(const glm::vec3&)>& radiance_rgb,
                                  int size, int band, int channel);

// Eq. 4's factors per band: the reflected radiance of incident field L along the lobe axis C is
// Σ_l factor_l Σ_m L_lm Y_lm(C). For a Lambert surface of unit albedo (eq. 6, C the normal) the
// factors are Â_l/π: 1, 2/3, 1/4, 0; for a normalised Phong lobe (n+1)/(2π)·cosⁿ around the mirror
// direction of unit reflectance (eq. 5), computed by quadrature (exact to float precision).
std::array<float, kShMaxBand + 1> lambertBandFactors();
// Eq. 4's factors 2π ∫₀¹ lobe(cosθ) P_l(cosθ) d(cosθ) of any lobe around its axis (zero below the
// horizon), by quadrature.
std::array<float, kShMaxBand + 1> zonalBandFactors(const std::function<double(double)>& lobe);
std::array<float, kShMaxBand + 1> phongBandFactors(double exponent);

}  // namespace gib::rt::sh
