// Exact solid angles of planar polygons, and of a convex area light partly hidden by a convex
// planar occluder: the closed form that Fournier & Péroche's bench test of hardware sampling of
// area lights (§6.1) compares against. Double precision throughout; angles in steradians.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace gib::scene {

// Solid angle (steradians, ≥ 0) that a planar simple polygon (vertices in order, either winding)
// subtends at x; 0 when x lies in its plane (within a relative 1e-12 of the polygon's distance
// from x) or when the polygon has fewer than three vertices or no area.
double polygonSolidAngle(const glm::dvec3& x, std::span<const glm::dvec3> polygon);

// The part of convex polygon `subject` inside convex polygon `clip` (2D, either winding each;
// Sutherland–Hodgman), in the winding of `subject`. Empty when they do not overlap (a shared edge
// or corner alone is no overlap) or when either has fewer than three vertices or no area.
std::vector<glm::dvec2> clipConvexPolygon(std::span<const glm::dvec2> subject,
                                          std::span<const glm::dvec2> clip);

// Solid angle at x of the part of the convex planar polygon `light` that x sees past the convex
// planar polygon `occluder`:
// Ω(light) − Ω(light ∩ central projection of the occluder from x onto the light's plane).
// Precondition (throws std::invalid_argument naming it): x is not in the light's plane, and every
// occluder vertex lies strictly between x and the light's plane (on x's side of that plane, and
// in front of x towards it). No one-sided test is applied: the solid angle is geometric, so either
// side of the light may face x. An occluder of fewer than three vertices hides nothing.
double visibleSolidAngle(const glm::dvec3& x, std::span<const glm::dvec3> light,
                         std::span<const glm::dvec3> occluder);

}  // namespace gib::scene
