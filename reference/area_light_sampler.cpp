#include "reference/area_light_sampler.h"

#include "reference/sampling.h"

#include <algorithm>

namespace gib::ref {

AreaLightSampler::AreaLightSampler(const scene::Scene& scene, const TriangleTable& triangles)
    : triangles_(triangles), pdf_area_(triangles.size(), 0.0f) {
  double total = 0;
  std::vector<double> power;
  for (std::uint32_t i = 0; i < triangles.size(); ++i) {
    const TriangleRecord& t = triangles[i];
    double p = double(scene::luminance(scene.materials[t.material].emission)) * t.area;
    if (p <= 0) continue;
    emitters_.push_back(i);
    power.push_back(p);
    total += p;
  }
  double running = 0;
  for (std::size_t k = 0; k < emitters_.size(); ++k) {
    running += power[k];
    cdf_.push_back(running / total);
    // P(triangle) / area = (L·A / total) / A.
    pdf_area_[emitters_[k]] = float(power[k] / total / triangles[emitters_[k]].area);
  }
  if (!cdf_.empty()) cdf_.back() = 1.0;
  for (std::size_t k = 0; k < cdf_.size(); ++k) {
    const double share = cdf_[k] - (k > 0 ? cdf_[k - 1] : 0.0);
    inverse_share_.push_back(share > 0 ? float(1.0 / share) : 0.0f);
  }
}

AreaLightSample AreaLightSampler::sample(glm::vec2 u) const {
  // u.x chooses the triangle, then is stretched back over [0, 1) inside the chosen interval and
  // reused: the one 2D point stays stratified over all emitters together, so the lights' share of
  // the noise falls at the rate of the point set, not as a coin toss per sample between
  // triangles (docs/rendering.md, "Sampling").
  auto it = std::upper_bound(cdf_.begin(), cdf_.end(), double(u.x));
  std::size_t k = std::min<std::size_t>(it - cdf_.begin(), emitters_.size() - 1);
  u.x = reuseAfterChoice(u.x, k > 0 ? float(cdf_[k - 1]) : 0.0f, inverse_share_[k]);
  AreaLightSample s;
  s.triangle = emitters_[k];
  glm::vec2 b = sampleUniformTriangle(u);
  // sampleUniformTriangle weights vertices 0 and 1; in edge form p = p0 + b1·e1 + b2·e2 with
  // b1 the weight of vertex 1 and b2 = 1 − b0 − b1 that of vertex 2.
  s.point = triangles_[s.triangle].point(b.y, 1.0f - b.x - b.y);
  s.pdf_area = pdf_area_[s.triangle];
  return s;
}

}  // namespace gib::ref
