// The reflection models of docs/architecture.md ("Materials") and docs/rendering.md ("Mirrors and
// glass"), evaluated and sampled in world space. Reflection is two-sided: the normals given are
// already turned towards ωo. Lambert and Phong are smooth lobes (path classes call them D); mirror
// and glass scatter into one or two discrete directions (S), so they are only sampled, never
// evaluated for a given pair of directions.
#pragma once

#include "scene/scene.h"

#include <glm/exponential.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace gib::ref {

using scene::Rgb;

// What a path carries through a vertex: radiance from the eye's side (the path tracer) or
// importance, i.e. flux, from the light's side (the light tracer). The two differ where transport
// is not symmetric (docs/rendering.md, "Shading normals"; "Mirrors and glass": refraction scales
// radiance by the square of the index ratio but not flux).
enum class Transport { kRadiance, kImportance };

// Beer–Lambert attenuation over a segment of length t that ends on a surface of `material`:
// exp(−absorption·t) where the segment ran inside glass (it ends on the back side), 1 elsewhere.
inline Rgb glassTransmittance(const scene::Material& material, bool ends_on_front, float t) {
  return material.type == scene::MaterialType::kGlass && !ends_on_front
             ? glm::exp(-material.absorption * t)
             : Rgb(1.0f);
}

struct BsdfSample {
  glm::vec3 wi{0.0f};
  Rgb f{0.0f};       // BSDF value for (wo, wi); zero for a specular sample
  float pdf = 0;     // solid-angle density of wi under `sample`; zero for a specular sample
  Rgb weight{0.0f};  // f·|cos θi|/pdf, what the path's throughput is multiplied by
  bool specular = false;
  bool refracted = false;  // wi crosses the surface (glass)
};

class Bsdf {
 public:
  // `geometric`: the triangle's normal turned towards wo; `shading`: the shading normal on the
  // same side (the geometric one for a flat surface); `outside`: wo lies on the front side of the
  // triangle, which for glass is the outside.
  Bsdf(const scene::Material& material, const glm::vec3& geometric, const glm::vec3& shading,
       const glm::vec3& wo, bool outside);
  // A Bsdf refers to its material, which must outlive it: not a temporary.
  Bsdf(scene::Material&&, const glm::vec3&, const glm::vec3&, const glm::vec3&, bool) = delete;

  bool isSpecular() const { return specular_; }

  // f(wo, wi): diffuse/π + specular·(n+2)/(2π)·cosⁿα; zero below the surface and for specular
  // materials.
  Rgb evaluate(const glm::vec3& wi) const;
  // f(wo, wi) times the cosine the transport equation integrates against: |ns·wi| for radiance,
  // and for importance |ns·wo|·|ng·wi|/|ng·wo| (Veach 1997, §5.3, eq. 5.19: the adjoint of a BSDF
  // shaded with a normal other than the geometric one). Zero where wi is below the geometric
  // surface. With ns = ng both are f·cos θi.
  Rgb evaluateProjected(const glm::vec3& wi, Transport transport = Transport::kRadiance) const;
  // Density of `sample` choosing wi (zero for specular materials).
  float pdf(const glm::vec3& wi) const;
  // Lambert and Phong: chooses the diffuse or the glossy lobe in proportion to their luminance
  // with u.x, then samples a cosine hemisphere or the Phong lobe around the mirror direction with
  // u (u.x stretched back over [0, 1)). A direction below the geometric surface comes back with
  // zero weight (the path ends there) but a valid pdf. Mirror: the mirror direction, weight F.
  // Glass: reflection with probability F, else refraction, weight 1 either way (times the index
  // ratio's square for radiance through refraction). See docs/rendering.md for the shading-normal
  // rule of specular directions.
  BsdfSample sample(glm::vec2 u, Transport transport = Transport::kRadiance) const;

  bool isBlack() const { return !specular_ && select_glossy_ <= 0 && diffuse_is_black_; }

 private:
  float glossyCos(const glm::vec3& wi) const;
  BsdfSample sampleSpecular(glm::vec2 u, Transport transport) const;
  // The adjoint's correction |ns·wo|·|ng·wi| / (|ng·wo|·|ns·wi|); 1 with ns = ng.
  float importanceCorrection(const glm::vec3& wi) const;

  const scene::Material& material_;
  glm::vec3 ng_;
  glm::vec3 ns_;
  glm::vec3 wo_;
  bool outside_;
  bool specular_;
  glm::vec3 mirror_;         // mirror direction of wo about ns
  float select_glossy_ = 0;  // probability of sampling the glossy lobe
  bool diffuse_is_black_ = true;
};

}  // namespace gib::ref
