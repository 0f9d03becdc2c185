// The optical depth of a particle medium along a ray, marched on the reference layer's density
// (scene/medium.h): an independent check for the real-time techniques' closed forms.
#pragma once

#include "scene/medium.h"

#include <glm/vec3.hpp>

namespace gib::test {

// ∫ σt(origin + t·direction) dt over [t0, t1] by the midpoint rule with `steps` steps.
double marchedOpticalDepth(const scene::DensityGrid& medium, const glm::vec3& origin,
                           const glm::vec3& direction, double t0, double t1, int steps);

}  // namespace gib::test
