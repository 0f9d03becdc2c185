// Solid angles of polygons against closed forms: an octant, rectangles seen from above a corner,
// and a light partly hidden by an occluder whose shadow is a rectangle too.
#include "scene/polygon_solid_angle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace gib::scene {
namespace {

constexpr double kPi = std::numbers::pi;
// Closed forms and the fan both take a handful of double operations per vertex: their results
// agree to a few ulps of 2π, so 1e-12 sr leaves three orders of magnitude of margin.
constexpr double kExact = 1e-12;

// The solid angle of the rectangle [0,a]×[0,b] at height h over a point under its corner (0,0):
// atan(ab / (h·√(h² + a² + b²))). Odd in a and in b, so that signed extents add up.
double cornerRectangle(double a, double b, double h) {
  return std::atan(a * b / (h * std::sqrt(h * h + a * a + b * b)));
}

// The rectangle [x0,x1]×[z0,z1] in the plane y = h seen from the origin, by inclusion–exclusion
// of the four rectangles that reach from under the origin to each corner.
double rectangleAbove(double x0, double x1, double z0, double z1, double h) {
  return cornerRectangle(x1, z1, h) - cornerRectangle(x0, z1, h) - cornerRectangle(x1, z0, h) +
         cornerRectangle(x0, z0, h);
}

// The axis-aligned square of side `side` centred at `centre`, in the plane y = centre.y.
std::vector<glm::dvec3> squareAt(glm::dvec3 centre, double side) {
  const double r = side / 2;
  return {centre + glm::dvec3(-r, 0, -r), centre + glm::dvec3(r, 0, -r),
          centre + glm::dvec3(r, 0, r), centre + glm::dvec3(-r, 0, r)};
}

double shoelaceArea(const std::vector<glm::dvec2>& polygon) {
  double sum = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2 p = polygon[i], q = polygon[(i + 1) % polygon.size()];
    sum += p.x * q.y - p.y * q.x;
  }
  return std::abs(sum) / 2;
}

std::vector<glm::dvec2> axisSquare(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

TEST(PolygonSolidAngle, OctantTriangleIsAnEighthOfTheSphere) {
  const std::vector<glm::dvec3> triangle = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  EXPECT_NEAR(polygonSolidAngle({0, 0, 0}, triangle), 4 * kPi / 8, kExact);
}

TEST(PolygonSolidAngle, RectangleOverACornerMatchesTheClosedFormInEitherWinding) {
  struct Case {
    double a, b, h;
  };
  for (const Case c : {Case{1, 1, 1}, Case{2, 0.5, 0.3}, Case{0.1, 3, 5}, Case{10, 10, 0.01},
                       Case{1e-3, 2e-3, 1e-3}}) {
    SCOPED_TRACE(testing::Message() << "a=" << c.a << " b=" << c.b << " h=" << c.h);
    std::vector<glm::dvec3> rectangle = {
        {0, 0, c.h}, {c.a, 0, c.h}, {c.a, c.b, c.h}, {0, c.b, c.h}};
    const double expected = cornerRectangle(c.a, c.b, c.h);
    EXPECT_NEAR(polygonSolidAngle({0, 0, 0}, rectangle), expected, kExact);
    std::reverse(rectangle.begin(), rectangle.end());
    EXPECT_NEAR(polygonSolidAngle({0, 0, 0}, rectangle), expected, kExact);
  }
}

TEST(PolygonSolidAngle, WidePolygonAboveItsInteriorExceedsPi) {
  // Seen from just above its interior a polygon fills nearly a hemisphere: the atan2 branch with a
  // negative denominator. A square of side 2L at height h subtends 4·atan(L² / (h√(h² + 2L²))).
  const std::vector<glm::dvec3> square = squareAt({0, 1e-3, 0}, 2);
  EXPECT_NEAR(polygonSolidAngle({0, 0, 0}, square), 4 * cornerRectangle(1, 1, 1e-3), kExact);
  EXPECT_GT(polygonSolidAngle({0, 0, 0}, square), kPi);
}

TEST(PolygonSolidAngle, PointInThePlaneSeesNothing) {
  const std::vector<glm::dvec3> square = squareAt({0, 0, 0}, 1);
  EXPECT_EQ(polygonSolidAngle({0.1, 0, 0.2}, square), 0.0);  // inside the polygon
  EXPECT_EQ(polygonSolidAngle({3, 0, -2}, square), 0.0);     // outside it
}

// The light of the occlusion tests: a unit square at y = 2, seen from a point on y = 0.
const std::vector<glm::dvec3> kLight = squareAt({0, 2, 0}, 1);
const glm::dvec3 kViewer(0.1, 0, -0.2);

TEST(PolygonSolidAngle, OccluderWhoseShadowCoversTheLightHidesAll) {
  // At y = 1 the shadow doubles: a square of side 2 under the light casts one of side 4.
  const std::vector<glm::dvec3> occluder = squareAt({0, 1, 0}, 2);
  EXPECT_NEAR(visibleSolidAngle(kViewer, kLight, occluder), 0.0, kExact);
}

TEST(PolygonSolidAngle, OccluderWhoseShadowMissesTheLightHidesNothing) {
  const std::vector<glm::dvec3> occluder = squareAt({3, 1, 0}, 0.2);
  EXPECT_EQ(visibleSolidAngle(kViewer, kLight, occluder), polygonSolidAngle(kViewer, kLight));
  EXPECT_NEAR(visibleSolidAngle(kViewer, kLight, occluder), rectangleAbove(-0.6, 0.4, -0.3, 0.7, 2),
              kExact);
}

TEST(PolygonSolidAngle, OccluderInsideTheLightsConeHidesItsShadow) {
  // At y = 1.5 the shadow is 4/3 the occluder's size, about the point under the occluder's
  // centre as seen from the viewer: side 0.3 → 0.4, centred at the viewer's (x, z), inside the
  // light. Both rectangles by the closed form, relative to the viewer.
  const std::vector<glm::dvec3> occluder = squareAt({0.1, 1.5, -0.2}, 0.3);
  const double light = rectangleAbove(-0.6, 0.4, -0.3, 0.7, 2);
  const double shadow = rectangleAbove(-0.2, 0.2, -0.2, 0.2, 2);
  EXPECT_NEAR(visibleSolidAngle(kViewer, kLight, occluder), light - shadow, kExact);
}

TEST(PolygonSolidAngle, PartialShadowLeavesTheRestOfTheLight) {
  // The shadow of a square of side 0.5 at y = 1 centred over (0.5, −0.5): side 1, centred at
  // 2·(0.5, −0.5) − (0.1, −0.2) = (0.9, −0.8), so it hides [0.4, 0.5]×[−0.5, −0.3] of the light.
  const std::vector<glm::dvec3> occluder = squareAt({0.5, 1, -0.5}, 0.5);
  const double light = rectangleAbove(-0.6, 0.4, -0.3, 0.7, 2);
  const double hidden = rectangleAbove(0.3, 0.4, -0.3, -0.1, 2);
  EXPECT_NEAR(visibleSolidAngle(kViewer, kLight, occluder), light - hidden, kExact);
}

TEST(PolygonSolidAngle, ClipOfOverlappingSquaresIsTheirOverlap) {
  const std::vector<glm::dvec2> a = axisSquare(0, 0, 2), b = axisSquare(1, 0.5, 2);
  EXPECT_NEAR(shoelaceArea(clipConvexPolygon(a, b)), 1.0 * 1.5, kExact);
  // Either winding of either polygon.
  const std::vector<glm::dvec2> b_reversed(b.rbegin(), b.rend());
  const std::vector<glm::dvec2> a_reversed(a.rbegin(), a.rend());
  EXPECT_NEAR(shoelaceArea(clipConvexPolygon(a, b_reversed)), 1.5, kExact);
  EXPECT_NEAR(shoelaceArea(clipConvexPolygon(a_reversed, b)), 1.5, kExact);
  EXPECT_NEAR(shoelaceArea(clipConvexPolygon(a_reversed, b_reversed)), 1.5, kExact);
}

TEST(PolygonSolidAngle, ClipOfDisjointSquaresIsEmpty) {
  EXPECT_TRUE(clipConvexPolygon(axisSquare(0, 0, 1), axisSquare(2, 0, 1)).empty());
  EXPECT_TRUE(clipConvexPolygon(axisSquare(0, 0, 1), axisSquare(1.5, 1.5, 1)).empty());
  // A shared edge alone is no overlap.
  EXPECT_TRUE(clipConvexPolygon(axisSquare(0, 0, 1), axisSquare(1, 0, 1)).empty());
}

TEST(PolygonSolidAngle, OccluderVertexOutsideTheSlabBreaksThePrecondition) {
  std::vector<glm::dvec3> beyond_light = squareAt({0, 1, 0}, 0.2);
  beyond_light[2].y = 2.5;
  EXPECT_THROW(visibleSolidAngle(kViewer, kLight, beyond_light), std::invalid_argument);
  std::vector<glm::dvec3> behind_viewer = squareAt({0, 1, 0}, 0.2);
  behind_viewer[0].y = -0.5;
  EXPECT_THROW(visibleSolidAngle(kViewer, kLight, behind_viewer), std::invalid_argument);
  const std::vector<glm::dvec3> in_light_plane = squareAt({0, 2, 0}, 0.2);
  EXPECT_THROW(visibleSolidAngle(kViewer, kLight, in_light_plane), std::invalid_argument);
}

TEST(PolygonSolidAngle, ViewerInTheLightsPlaneBreaksThePrecondition) {
  const std::vector<glm::dvec3> occluder = squareAt({0, 1, 0}, 0.2);
  EXPECT_THROW(visibleSolidAngle({3, 2, 0}, kLight, occluder), std::invalid_argument);
}

}  // namespace
}  // namespace gib::scene
