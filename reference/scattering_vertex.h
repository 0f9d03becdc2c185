// A point where a path scatters: on a surface (BSDF, cosine, offset for spawned rays) or inside
// the medium (phase function, no offset). Next-event estimation and MIS treat both alike.
#pragma once

#include "reference/bsdf.h"
#include "reference/phase_function.h"
#include "reference/sampling.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace gib::ref {

// Density of sky next-event estimation at a vertex: the uniform sphere in the medium, the uniform
// hemisphere above a surface with the given normal.
inline float skySamplingPdf(bool in_medium, const glm::vec3& normal, const glm::vec3& wi) {
  if (in_medium) return 1.0f / (4.0f * kPi);
  return glm::dot(normal, wi) > 0 ? kUniformHemispherePdf : 0.0f;
}

struct ScatteringVertex {
  glm::vec3 point{0.0f};
  const Bsdf* bsdf = nullptr;      // null inside the medium
  glm::vec3 normal{0.0f};          // surfaces: geometric normal turned towards wo
  glm::vec3 shading_normal{0.0f};  // surfaces: shading normal on the same side
  float epsilon = 0;               // surfaces: offset of spawned rays along the normal
  glm::vec3 direction{0.0f};       // medium: propagation direction of the arriving path
  float g = 0;                     // medium: Henyey–Greenstein asymmetry

  bool inMedium() const { return bsdf == nullptr; }

  // The scattered fraction towards wi: f·cos θ on a surface (Bsdf::evaluateProjected), the
  // phase function in the medium.
  scene::Rgb evaluate(const glm::vec3& wi, Transport transport = Transport::kRadiance) const {
    if (inMedium()) return scene::Rgb(henyeyGreenstein(glm::dot(direction, wi), g));
    return bsdf->evaluateProjected(wi, transport);
  }
  // Density with which the vertex's own sampling strategy picks wi.
  float pdf(const glm::vec3& wi) const {
    return inMedium() ? henyeyGreenstein(glm::dot(direction, wi), g) : bsdf->pdf(wi);
  }
  float skyPdf(const glm::vec3& wi) const { return skySamplingPdf(inMedium(), normal, wi); }
  glm::vec3 sampleSkyDirection(glm::vec2 u) const {
    if (inMedium()) {
      const float z = 1.0f - 2.0f * u.x;
      const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
      return {r * std::cos(2.0f * kPi * u.y), r * std::sin(2.0f * kPi * u.y), z};
    }
    return Frame(normal).toWorld(sampleUniformHemisphere(u));
  }
  glm::vec3 spawnOrigin() const { return point + epsilon * normal; }
};

}  // namespace gib::ref
