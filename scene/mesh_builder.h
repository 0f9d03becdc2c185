// Small helpers for building meshes in code (built-in and procedural scenes).
#pragma once

#include "scene/scene.h"

#include <string>

namespace gib::scene {

// Appends `material` to the scene and an empty mesh of that material named `name`, and returns the
// mesh to build into: an object of its own material (a mirror or glass sphere, a fire ball), as
// the built-in scenes add them. The reference stays valid until the next mesh is added.
Mesh& addMeshOfMaterial(Scene& scene, std::string name, Material material);

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

// Appends a closed, watertight torus facing outwards, smooth-shaded (the exact torus normal at
// every vertex, as a smooth sphere's): the tube of `minor_radius` swept around the circle of
// `major_radius` about `axis` (any non-zero direction) through `centre`, with `rings` sections
// around the axis and `segments` around the tube. A stand-in for the book's curved objects (the
// teapot of Fig. 6.9, the bunny and dragon of Figs. 7.11 and 7.13): a surface of both curvatures
// with a hole, which sees itself. The mesh must have a normal for every vertex (or none yet).
void appendTorus(Mesh& mesh, glm::vec3 centre, glm::vec3 axis, float major_radius,
                 float minor_radius, int rings, int segments);

// Appends the closed parallelepiped centre ± u ± v ± w (u, v, w half the edge vectors, not
// coplanar) as 12 triangles on 8 shared vertices, facing outwards whichever handedness u, v, w
// have; flat-shaded. A thin one is a pane of glass or a mirror panel (glass meshes must be closed).
void appendParallelepiped(Mesh& mesh, glm::vec3 centre, glm::vec3 u, glm::vec3 v, glm::vec3 w);

}  // namespace gib::scene
