// Warps from the unit square to directions and points, with their densities. Local directions
// are in a frame whose z axis is the normal (or lobe axis).
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <numbers>

namespace gib::ref {

inline constexpr float kPi = std::numbers::pi_v<float>;
inline constexpr float kInvPi = 1.0f / kPi;
// The largest float below 1: uniform numbers live in [0, 1).
inline constexpr float kOneBelow = 0x1.fffffep-1f;

// A uniform number u in [0, 1) that chose the interval [low, low + width) of [0, 1), stretched
// back over [0, 1): uniform again and independent of the choice, so one number can make a
// discrete choice and then place a point, and a stratified point set stays stratified across
// the choices. Takes 1 / width: a division here would sit on every path's critical chain.
inline float reuseAfterChoice(float u, float low, float inverse_width) {
  const float reused = (u - low) * inverse_width;
  return reused < 0.0f ? 0.0f : (reused < kOneBelow ? reused : kOneBelow);
}

// An orthonormal basis around a unit vector (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited": branchless and continuous except at n.z = −1 handled by the sign).
struct Frame {
  glm::vec3 s, t, n;

  explicit Frame(const glm::vec3& normal);
  glm::vec3 toWorld(const glm::vec3& v) const { return v.x * s + v.y * t + v.z * n; }
  glm::vec3 toLocal(const glm::vec3& v) const {
    return {glm::dot(v, s), glm::dot(v, t), glm::dot(v, n)};
  }
};

// Cosine-weighted hemisphere around +z: pdf = cos θ / π.
glm::vec3 sampleCosineHemisphere(glm::vec2 u);
inline float cosineHemispherePdf(float cos_theta) {
  return cos_theta > 0 ? cos_theta * kInvPi : 0;
}

// Uniform hemisphere around +z: pdf = 1 / 2π.
glm::vec3 sampleUniformHemisphere(glm::vec2 u);
inline constexpr float kUniformHemispherePdf = 1.0f / (2.0f * kPi);

// Phong lobe cosⁿα around +z, normalised as a density over the sphere: pdf = (n+1)/(2π)·cosⁿα
// for cos α > 0.
glm::vec3 samplePhongLobe(glm::vec2 u, float exponent);
float phongLobePdf(float cos_alpha, float exponent);

// Uniform point on a triangle, as barycentric weights (b0, b1) of vertices 0 and 1.
glm::vec2 sampleUniformTriangle(glm::vec2 u);

}  // namespace gib::ref
