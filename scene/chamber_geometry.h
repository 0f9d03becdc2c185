// Builders for the procedural marble chamber (chamber.cpp): tessellated patches, boxes, pillar
// shafts, arches and the barrel vault. Determinism: no random numbers and no unordered
// containers; every builder computes its points in double with IEEE arithmetic and rounds each
// coordinate to float once, so that the same triangles come out on every x86-64 machine. The
// rounding also absorbs last-bit differences in the double results (FMA contraction, another
// libm: see unitCirclePoint) unless one falls on a float rounding boundary, which the scene hash
// test would catch. (The hash is the same built with GCC -O0, Clang -O3 and GCC -O3 -march=native
// -ffp-contract=fast.)
#pragma once

#include "scene/scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <functional>

namespace gib::scene::chamber {

// The point at angle π·i/n on the unit circle, for 0 ≤ i ≤ 2n and even n. Exactly (1, 0), (0, 1),
// (−1, 0), (0, −1) at the quarter turns, and mirror-symmetric about both axes (and about 45°
// when n is a multiple of 4): the two halves of an arch are exact mirror images, whatever libm
// does. Only angles up to 45° reach std::cos/std::sin (double); glibc computes these to within an
// ulp, and the result is rounded to float afterwards, so a difference between libm versions
// could change a vertex only if it fell on a float rounding boundary.
glm::dvec2 unitCirclePoint(int i, int n);

// A tessellated surface patch: the points point(i, j) for 0 ≤ i ≤ nu, 0 ≤ j ≤ nv, joined into
// 2·nu·nv triangles. Each triangle's front side is the one whose normal has a positive dot product
// with facing(centroid): the caller says which way is "into the hall" and the winding follows.
using PatchPoint = std::function<glm::dvec3(int i, int j)>;
using PatchFacing = std::function<glm::dvec3(glm::dvec3 centroid)>;
// Cells (i, j) (0 ≤ i < nu, 0 ≤ j < nv) for which `leave_out` is true get no triangles: holes of
// whole cells. Every point is still added (a hole's own corners are shared with the cells around
// it), so that the vertex list, and with no holes the whole mesh, is what it is without them.
using PatchCells = std::function<bool(int i, int j)>;
void appendPatch(Mesh& mesh, int nu, int nv, const PatchPoint& point, const PatchFacing& facing,
                 const PatchCells& leave_out = {});

// The parallelogram corner + s·u + t·v (s, t ∈ [0, 1]) split into nu × nv cells, front side
// towards `facing`.
void appendPanel(Mesh& mesh, glm::dvec3 corner, glm::dvec3 u, glm::dvec3 v, int nu, int nv,
                 glm::dvec3 facing);

// The faces of the axis-aligned box [lo, hi], facing outwards, each split into `cells` × `cells`;
// the bottom face is left out when the box stands on the floor (it would never be seen).
void appendBox(Mesh& mesh, glm::dvec3 lo, glm::dvec3 hi, int cells, bool with_bottom);

// The side of a vertical cylinder (no caps) standing at base_centre, facing outwards, with
// `segments` (a multiple of 4) around and `rows` up.
void appendShaft(Mesh& mesh, glm::dvec3 base_centre, double radius, double height, int segments,
                 int rows);

// A barrel vault: the upper half of the cylinder of `radius` around the axis (x = 0, y = spring_y)
// from z0 to z1, facing the axis (into the hall), with `segments` (even) across and `rows` along.
// `openings` leaves out the cells (i across from x = +radius, j along from z0) it names: roof
// lights whose edges are the vault's own grid lines.
void appendBarrelVault(Mesh& mesh, double spring_y, double radius, double z0, double z1,
                       int segments, int rows, const PatchCells& openings = {});

// The half disc that closes a barrel vault at its end wall z = z: centre (0, spring_y), `segments`
// around (even) and `rings` from the centre out, front side towards facing_z (±1).
void appendLunette(Mesh& mesh, double z, double facing_z, double spring_y, double radius,
                   int segments, int rings);

// The underside (intrados) of a round arch: a semicircle in the plane x = const of `radius`
// around (centre_z, spring_y), swept from x0 to x1; faces the arch's axis.
void appendArchSoffit(Mesh& mesh, double x0, double x1, double centre_z, double spring_y,
                      double radius, int segments, int rows);

// One face of an arcade wall over a bay: the rectangle z ∈ [z0, z1], y ∈ [spring_y, top_y] in the
// plane x = x, less the semicircular arch opening of `radius` centred at ((z0 + z1)/2, spring_y).
// Strips run from each arch segment out to the rectangle's edge (`rows` quads deep); the front
// side faces facing_x (±1).
void appendSpandrel(Mesh& mesh, double x, double facing_x, double z0, double z1, double spring_y,
                    double top_y, double radius, int segments, int rows);

}  // namespace gib::scene::chamber
