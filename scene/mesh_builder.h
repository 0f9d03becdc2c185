// Small helpers for building meshes in code (built-in and procedural scenes).
#pragma once

#include "scene/scene.h"

namespace gib::scene {

// Appends the quad a-b-c-d as triangles (a,b,c) and (a,c,d); its front side is the side that
// (b − a) × (c − a) points to. The four points need not be exactly planar.
void appendQuad(Mesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d);

// How a tessellated sphere is shaded: flat triangles (no vertex normals), or smooth, with the
// exact sphere normal at every vertex as its shading normal (Mesh::normals), which renders the
// sphere rather than its facets (mirrors and glass magnify facets).
enum class SphereShading { kFlat, kSmooth };

// Appends a closed, watertight UV sphere (shared vertices, poles included) with `rings` latitude
// bands and `segments` longitude bands. Triangles face outwards unless `inward` is set; smooth
// shading normals point to the same side. A smooth sphere needs a mesh whose vertices all have
// normals (or none yet), a flat one a mesh without normals: mixing them is a std::logic_error.
void appendSphere(Mesh& mesh, glm::vec3 centre, float radius, int rings, int segments, bool inward,
                  SphereShading shading = SphereShading::kFlat);

}  // namespace gib::scene
