// The Delaunay triangulation of directions on the unit sphere (book §4.2.3): the convex hull of
// the points, built by incremental insertion. Inserting a point deletes every triangle whose
// plane has the point on its outer side (on the sphere, exactly the triangles whose circumcircle
// contains it: Bowyer–Watson) and connects the point to the horizon of the cavity. In double
// precision with a filtered orientation predicate (the determinant against a bound on its
// rounding error): a point that no face sees by more than that bound lies on the hull already (a
// duplicate, or within rounding of one) and is skipped, never jittered. O(n²) in all (each
// insertion scans the faces), a few milliseconds for the thousand points of Fig. 4.15.
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <vector>

namespace gib::rt {

struct SphericalDelaunay {
  // Counter-clockwise seen from outside the sphere; indices into the points given.
  std::vector<std::array<int, 3>> triangles;
  // Points left out: duplicates of an earlier point (within rounding).
  std::vector<int> skipped;
};

// The triangulation of unit vectors `points`. A set without four points off one plane (fewer
// than four, or all on one circle) has no closed hull and gives no triangles.
SphericalDelaunay triangulateSphere(const std::vector<glm::dvec3>& points);

// The sign of the orientation of d against the plane of (a, b, c), counter-clockwise seen from
// the positive side: +1 when d lies on the side (b − a) × (c − a) points to, −1 on the other, 0
// when within the determinant's rounding bound of the plane.
int orientation(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d);

}  // namespace gib::rt
