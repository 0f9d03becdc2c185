// The per-frame work of PRT on the CPU (book §8.3, eq. 8.5): the lighting turned about +y, then
// its dot products with every cluster's mean and basis vectors, 3·K·(M + 1) of them, which the
// vertex shader weighs and sums.
#pragma once

#include "realtime/prt/cpca.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <span>
#include <vector>

namespace gib::rt::prt {

// `lighting`: bands² RGB coefficients; `rotated` receives them turned by `angle` radians about +y
// (rotateAboutY; a copy when the angle is 0). out[k·(M + 1) + d] = (L·M^k) for d = 0 and
// (L·B_{d−1}^k) after it, per channel in xyz (w 0), for vectors laid out as Transfer::vectors
// (red's bands² coefficients, then green's, then blue's). `out` holds K·(M + 1) entries.
void projectLighting(const CpcaResult& compressed, std::span<const glm::vec3> lighting, int bands,
                     float angle, std::vector<glm::vec3>& rotated, std::span<glm::vec4> out);

}  // namespace gib::rt::prt
