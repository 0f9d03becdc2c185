// The reflection models of docs/architecture.md ("Materials"), evaluated and sampled in world
// space. Reflection is two-sided: `n` is the surface normal already turned towards ωo.
#pragma once

#include "scene/scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace gib::ref {

using scene::Rgb;

struct BsdfSample {
  glm::vec3 wi{0.0f};
  Rgb f{0.0f};    // BSDF value for (wo, wi)
  float pdf = 0;  // solid-angle density of wi under `sample`
};

class Bsdf {
 public:
  Bsdf(const scene::Material& material, const glm::vec3& n, const glm::vec3& wo);

  // f(wo, wi): diffuse/π + specular·(n+2)/(2π)·cosⁿα; zero below the surface.
  Rgb evaluate(const glm::vec3& wi) const;
  // Density of `sample` choosing wi.
  float pdf(const glm::vec3& wi) const;
  // Chooses the diffuse or the glossy lobe in proportion to their luminance with u.x, then
  // samples a cosine hemisphere or the Phong lobe around the mirror direction with u (u.x
  // stretched back over [0, 1)). A direction below the surface comes back with f = 0 (the path
  // ends there) but a valid pdf.
  BsdfSample sample(glm::vec2 u) const;

  bool isBlack() const { return select_glossy_ <= 0 && diffuse_is_black_; }

 private:
  float glossyCos(const glm::vec3& wi) const;

  const scene::Material& material_;
  glm::vec3 n_;
  glm::vec3 mirror_;         // mirror direction of wo about n
  float select_glossy_ = 0;  // probability of sampling the glossy lobe
  bool diffuse_is_black_ = true;
};

}  // namespace gib::ref
