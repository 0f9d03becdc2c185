// Small helpers for building meshes in code (built-in and procedural scenes).
#pragma once

#include "scene/scene.h"

namespace gib::scene {

// Appends the quad a-b-c-d as triangles (a,b,c) and (a,c,d); its front side is the side that
// (b − a) × (c − a) points to. The four points need not be exactly planar.
void appendQuad(Mesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d);

// Appends a closed, watertight UV sphere (shared vertices, poles included) with `rings` latitude
// bands and `segments` longitude bands. Triangles face outwards unless `inward` is set.
void appendSphere(Mesh& mesh, glm::vec3 centre, float radius, int rings, int segments, bool inward);

}  // namespace gib::scene
