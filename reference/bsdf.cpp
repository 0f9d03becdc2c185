#include "reference/bsdf.h"

#include "reference/sampling.h"
#include "scene/fresnel_shared.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace gib::ref {

namespace {

glm::vec3 reflect(const glm::vec3& wo, const glm::vec3& n) {
  return 2.0f * glm::dot(n, wo) * n - wo;
}

// The direction refracted from wo through a surface with normal n on wo's side, for the index
// ratio eta = η(behind)/η(wo's side) and cos θt already known (no total internal reflection).
glm::vec3 refract(const glm::vec3& wo, const glm::vec3& n, float eta, float cos_t) {
  return glm::normalize(-wo / eta + (glm::dot(n, wo) / eta - cos_t) * n);
}

}  // namespace

Bsdf::Bsdf(const scene::Material& material, const glm::vec3& geometric, const glm::vec3& shading,
           const glm::vec3& wo, bool outside)
    : material_(material),
      ng_(geometric),
      ns_(shading),
      wo_(wo),
      outside_(outside),
      specular_(scene::isIdealSpecular(material.type)),
      mirror_(reflect(wo, shading)) {
  if (specular_) return;
  float yd = scene::luminance(material.diffuse);
  float ys = material.type == scene::MaterialType::kPhong ? scene::luminance(material.specular) : 0;
  diffuse_is_black_ = yd <= 0;
  select_glossy_ = (yd + ys) > 0 ? ys / (yd + ys) : 0;
}

float Bsdf::glossyCos(const glm::vec3& wi) const {
  return glm::dot(mirror_, wi);
}

Rgb Bsdf::evaluate(const glm::vec3& wi) const {
  if (specular_ || glm::dot(ng_, wi) <= 0) return Rgb(0.0f);
  Rgb f = material_.diffuse * kInvPi;
  if (material_.type == scene::MaterialType::kPhong) {
    float c = glossyCos(wi);
    if (c > 0) {
      float n = material_.exponent;
      f += material_.specular * ((n + 2.0f) * 0.5f * kInvPi * std::pow(c, n));
    }
  }
  return f;
}

float Bsdf::importanceCorrection(const glm::vec3& wi) const {
  const float denominator = std::abs(glm::dot(ng_, wo_)) * std::abs(glm::dot(ns_, wi));
  return denominator > 0 ? std::abs(glm::dot(ns_, wo_)) * std::abs(glm::dot(ng_, wi)) / denominator
                         : 0.0f;
}

Rgb Bsdf::evaluateProjected(const glm::vec3& wi, Transport transport) const {
  const float cos_s = std::max(0.0f, glm::dot(ns_, wi));
  const Rgb projected = evaluate(wi) * cos_s;
  return transport == Transport::kRadiance ? projected : projected * importanceCorrection(wi);
}

float Bsdf::pdf(const glm::vec3& wi) const {
  if (specular_) return 0;
  float cos_theta = glm::dot(ns_, wi);
  if (cos_theta <= 0) return 0;
  float p = (1.0f - select_glossy_) * cosineHemispherePdf(cos_theta);
  if (select_glossy_ > 0) p += select_glossy_ * phongLobePdf(glossyCos(wi), material_.exponent);
  return p;
}

BsdfSample Bsdf::sampleSpecular(glm::vec2 u, Transport transport) const {
  BsdfSample s;
  s.specular = true;
  // The shading normal decides the directions unless it sends the path to the wrong side of the
  // geometric surface (near silhouettes of coarse meshes); then the geometric normal does, for
  // this scattering event only. Either way the weight is that of a lossless interface (1 for a
  // perfect mirror or clear glass), so a closed lossless object stays lossless (the furnace test).
  auto scatter = [&](const glm::vec3& n) {
    const float cos_o = glm::dot(n, wo_);
    if (material_.type == scene::MaterialType::kMirror) {
      s.wi = reflect(wo_, n);
      s.weight = material_.perfect_mirror
                     ? Rgb(1.0f)
                     : scene::fresnelConductor(cos_o, material_.conductor_n, material_.conductor_k);
      s.refracted = false;
      return glm::dot(ng_, s.wi) > 0;
    }
    const float eta = outside_ ? material_.ior : 1.0f / material_.ior;
    const float reflectance = scene::fresnelDielectric(cos_o, eta);
    s.weight = Rgb(1.0f);
    if (u.x < reflectance) {
      s.wi = reflect(wo_, n);
      s.refracted = false;
      return glm::dot(ng_, s.wi) > 0;
    }
    const float sin2_t = (1.0f - cos_o * cos_o) / (eta * eta);
    s.wi = refract(wo_, n, eta, std::sqrt(std::max(0.0f, 1.0f - sin2_t)));
    s.refracted = true;
    // Radiance is η²-compressed on entering a denser medium (docs/rendering.md, "Mirrors and
    // glass"); flux is not.
    if (transport == Transport::kRadiance) s.weight /= eta * eta;
    return glm::dot(ng_, s.wi) < 0;
  };
  if (!scatter(ns_)) scatter(ng_);
  if (transport == Transport::kImportance) s.weight *= importanceCorrection(s.wi);
  return s;
}

BsdfSample Bsdf::sample(glm::vec2 u, Transport transport) const {
  if (specular_) return sampleSpecular(u, transport);
  BsdfSample s;
  if (isBlack()) return s;
  // u.x picks the lobe and is reused for the direction (reuseAfterChoice); with one lobe it
  // is used as it is.
  const bool mixed = select_glossy_ > 0 && select_glossy_ < 1;
  if (u.x < select_glossy_) {
    if (mixed) u.x = reuseAfterChoice(u.x, 0.0f, 1.0f / select_glossy_);
    s.wi = Frame(mirror_).toWorld(samplePhongLobe(u, material_.exponent));
  } else {
    if (mixed) u.x = reuseAfterChoice(u.x, select_glossy_, 1.0f / (1.0f - select_glossy_));
    s.wi = Frame(ns_).toWorld(sampleCosineHemisphere(u));
  }
  s.pdf = pdf(s.wi);
  s.f = evaluate(s.wi);
  const float cos_wi = glm::dot(ns_, s.wi);
  if (s.pdf > 0 && cos_wi > 0) {
    s.weight = s.f * (cos_wi / s.pdf);
    if (transport == Transport::kImportance) s.weight *= importanceCorrection(s.wi);
  }
  return s;
}

}  // namespace gib::ref
