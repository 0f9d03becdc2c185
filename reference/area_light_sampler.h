// Picks a point on the emissive triangles with probability proportional to emitted power
// (luminance of the radiance × area), for next-event estimation.
#pragma once

#include "reference/triangle_table.h"

#include <glm/vec2.hpp>

#include <vector>

namespace gib::ref {

struct AreaLightSample {
  glm::vec3 point{0.0f};
  std::uint32_t triangle = 0;  // global index
  float pdf_area = 0;          // density per unit area over all emitting surfaces
};

class AreaLightSampler {
 public:
  AreaLightSampler(const scene::Scene& scene, const TriangleTable& triangles);

  bool empty() const { return emitters_.empty(); }
  // One uniform 2D point chooses the triangle (by its first coordinate) and the point on it.
  AreaLightSample sample(glm::vec2 u) const;
  // Density per unit area at a point of the given triangle (0 for a non-emitter).
  float pdfArea(std::uint32_t triangle) const { return pdf_area_[triangle]; }

 private:
  const TriangleTable& triangles_;
  std::vector<std::uint32_t> emitters_;  // global indices of emitting triangles
  std::vector<double> cdf_;              // cumulative power, normalised to 1
  std::vector<float> inverse_share_;     // 1 / (cdf_[k] − cdf_[k − 1])
  std::vector<float> pdf_area_;          // per global triangle
};

}  // namespace gib::ref
