#include "reference/bsdf.h"

#include "reference/sampling.h"

#include <cmath>

namespace gib::ref {

Bsdf::Bsdf(const scene::Material& material, const glm::vec3& n, const glm::vec3& wo)
    : material_(material), n_(n), mirror_(2.0f * glm::dot(n, wo) * n - wo) {
  float yd = scene::luminance(material.diffuse);
  float ys = material.type == scene::MaterialType::kPhong ? scene::luminance(material.specular) : 0;
  diffuse_is_black_ = yd <= 0;
  select_glossy_ = (yd + ys) > 0 ? ys / (yd + ys) : 0;
}

float Bsdf::glossyCos(const glm::vec3& wi) const {
  return glm::dot(mirror_, wi);
}

Rgb Bsdf::evaluate(const glm::vec3& wi) const {
  if (glm::dot(n_, wi) <= 0) return Rgb(0.0f);
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

float Bsdf::pdf(const glm::vec3& wi) const {
  float cos_theta = glm::dot(n_, wi);
  if (cos_theta <= 0) return 0;
  float p = (1.0f - select_glossy_) * cosineHemispherePdf(cos_theta);
  if (select_glossy_ > 0) p += select_glossy_ * phongLobePdf(glossyCos(wi), material_.exponent);
  return p;
}

BsdfSample Bsdf::sample(glm::vec2 u) const {
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
    s.wi = Frame(n_).toWorld(sampleCosineHemisphere(u));
  }
  s.pdf = pdf(s.wi);
  s.f = evaluate(s.wi);
  return s;
}

}  // namespace gib::ref
