// Rotation of real spherical-harmonic coefficient vectors (sh_basis.h's order and convention):
// the coefficients of the rotated function g(ω) = f(R⁻¹ω) from those of f, band by band (a
// rotation never mixes bands; "rotational invariance", book §8.3). The general rotation builds
// each band's (2l+1)² matrix from the 3×3 matrix by the recurrences of Ivanic & Ruedenberg,
// "Rotation matrices for real spherical harmonics. Direct determination by recursion",
// J. Phys. Chem. 100 (1996) 6342–6347, with the corrections of their "Additions and
// corrections", J. Phys. Chem. A 102 (1998) 9099–9100. Rotations about +z (the basis's polar
// axis) only turn each pair (m, −m) by the angle m·α.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace gib::rt::sh {

class ShRotation {
 public:
  // `rotation` a proper rotation matrix (orthonormal, determinant 1; glm's column-major
  // matrix R acting as R·v), `bands` as in evaluateShBasis (1..8). The matrices are computed in
  // double; the float overload rounds its input once.
  ShRotation(const glm::dmat3& rotation, int bands);
  ShRotation(const glm::mat3& rotation, int bands);

  int bands() const { return bands_; }
  // Band l's matrix D^l, (2l+1)², row-major, rows and columns m = −l..l: out_m = Σ_n D_mn in_n.
  std::span<const double> bandMatrix(int l) const;

  // out = D·in over the first bands² coefficients (in and out may not overlap; each must hold
  // at least bands² values, the rest of out is left alone).
  void apply(std::span<const float> in, std::span<float> out) const;
  void apply(std::span<const double> in, std::span<double> out) const;
  // RGB coefficients: each channel rotated alike.
  void apply(std::span<const glm::vec3> in, std::span<glm::vec3> out) const;
  std::vector<glm::vec3> apply(std::span<const glm::vec3> in) const;

 private:
  int bands_;
  std::vector<double> matrices_;  // band after band, (2l+1)² each
};

// g(ω) = f(R_z(angle)⁻¹ω) in place, angle in radians, right-handed about +z (+x turns towards
// +y): c_m ← c_m cos mα − c_{−m} sin mα, c_{−m} ← c_m sin mα + c_{−m} cos mα. O(bands²).
void rotateAboutZ(std::span<float> coefficients, int bands, float angle);
void rotateAboutZ(std::span<glm::vec3> coefficients, int bands, float angle);

// g(ω) = f(R_y(angle)⁻¹ω) in place, angle in radians, right-handed about +y (+x turns towards
// −z: the environment map's rotation_deg, scene/environment_map.h). +y is not the basis's polar
// axis, so this conjugates rotateAboutZ by the fixed quarter turn Q = R_x(−90°) that takes +z to
// +y: D(R_y(α)) = D(Q)·D(R_z(α))·D(Q)ᵀ, two products with cached band matrices instead of the
// recurrences for every angle.
void rotateAboutY(std::span<float> coefficients, int bands, float angle);
void rotateAboutY(std::span<glm::vec3> coefficients, int bands, float angle);

}  // namespace gib::rt::sh
