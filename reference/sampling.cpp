#include "reference/sampling.h"

#include <algorithm>
#include <cmath>

namespace gib::ref {

Frame::Frame(const glm::vec3& normal) : n(normal) {
  float sign = std::copysign(1.0f, n.z);
  float a = -1.0f / (sign + n.z);
  float b = n.x * n.y * a;
  s = {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
  t = {b, sign + n.y * n.y * a, -n.y};
}

glm::vec3 sampleCosineHemisphere(glm::vec2 u) {
  // Malley's method: a uniform point on the disk, projected up to the hemisphere.
  float r = std::sqrt(u.x);
  float phi = 2.0f * kPi * u.y;
  float z = std::sqrt(std::max(0.0f, 1.0f - u.x));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

glm::vec3 sampleUniformHemisphere(glm::vec2 u) {
  float z = u.x;
  float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  float phi = 2.0f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

glm::vec3 samplePhongLobe(glm::vec2 u, float exponent) {
  // Inverting the CDF of (n+1)·cosⁿα·sin α over α gives cos α = u^(1/(n+1)).
  float cos_alpha = std::pow(u.x, 1.0f / (exponent + 1.0f));
  float sin_alpha = std::sqrt(std::max(0.0f, 1.0f - cos_alpha * cos_alpha));
  float phi = 2.0f * kPi * u.y;
  return {sin_alpha * std::cos(phi), sin_alpha * std::sin(phi), cos_alpha};
}

float phongLobePdf(float cos_alpha, float exponent) {
  if (cos_alpha <= 0) return 0;
  return (exponent + 1.0f) * (0.5f * kInvPi) * std::pow(cos_alpha, exponent);
}

glm::vec2 sampleUniformTriangle(glm::vec2 u) {
  float su = std::sqrt(u.x);
  return {1.0f - su, u.y * su};
}

}  // namespace gib::ref
