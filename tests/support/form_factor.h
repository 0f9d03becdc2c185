// Closed forms of diffuse transfer that tests compare GPU transfer against.
#pragma once

#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <vector>

namespace gib::test {

// Lambert's formula: the form factor from a differential area at x (unit normal n) to a planar
// polygon (its vertices in order), i.e. (1/π)∫ cos θ_x cos θ_y / r² dA over the polygon.
double pointToPolygonFormFactor(const glm::dvec3& x, const glm::dvec3& n,
                                const std::vector<glm::dvec3>& polygon);

// Two parallel unit squares one unit apart, face to face: mesh 0 (triangles 0 and 1) the top one,
// [0,1]×{1}×[0,1] facing −y, of material 0; mesh 1 (triangles 2 and 3) the bottom one at y = 0
// facing +y, of material 1. A camera looks at them from the side.
scene::Scene facingUnitSquares(const scene::Material& top, const scene::Material& bottom);

// A unit square at height 1 centred over the origin, facing down (−y): its corners in order, and
// `scene` with it added as a mesh of material 0 (a patch over the floor of the gather tests).
const std::vector<glm::dvec3>& unitPatchCorners();
scene::Scene withUnitPatch(scene::Scene scene);

}  // namespace gib::test
