// The Henyey–Greenstein phase function of the medium (docs/architecture.md, "Media"), as a density
// over the sphere of outgoing propagation directions.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace gib::ref {

// p(θ) = (1 − g²) / (4π (1 + g² − 2g cos θ)^{3/2}), θ between the propagation directions before
// and after scattering; integrates to 1 over the sphere.
float henyeyGreenstein(float cos_theta, float g);

// A new propagation direction for a photon travelling along `direction`, distributed by
// henyeyGreenstein (so the pdf of the result is henyeyGreenstein(dot(direction, result), g)).
glm::vec3 sampleHenyeyGreenstein(const glm::vec3& direction, float g, glm::vec2 u);

}  // namespace gib::ref
