#include "scene/polygon_solid_angle.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace gib::scene {
namespace {

// A point whose distance from a polygon's plane is below this fraction of its distance from the
// farthest vertex counts as in the plane: rounding puts ~1e-16 of that distance there, so 1e-12
// is far above rounding and far below any geometry a scene means.
constexpr double kInPlaneTolerance = 1e-12;
// A clipped polygon whose area is below this fraction of the smaller input's area is what
// Sutherland–Hodgman leaves of a shared edge or corner (collinear points, area zero up to
// rounding), not an overlap.
constexpr double kSliverArea = 1e-14;

// Twice the vector area (Newell's normal): perpendicular to a planar polygon, of length twice its
// area, pointing to the side from which the vertices run counter-clockwise. Summed over a fan
// from vertex 0, which gives the same vector for any simple planar polygon, convex or not, and
// loses no precision to cancellation when the polygon is far from the origin.
glm::dvec3 vectorArea(std::span<const glm::dvec3> polygon) {
  glm::dvec3 normal(0.0);
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
    normal += glm::cross(polygon[i] - polygon[0], polygon[i + 1] - polygon[0]);
  return normal;
}

double farthestVertexDistance(const glm::dvec3& x, std::span<const glm::dvec3> polygon) {
  double farthest = 0;
  for (const glm::dvec3& v : polygon) farthest = std::max(farthest, glm::length(v - x));
  return farthest;
}

// `height` is x's signed distance from the plane of `polygon` (see kInPlaneTolerance).
bool liesInPlane(const glm::dvec3& x, std::span<const glm::dvec3> polygon, double height) {
  return std::abs(height) <= kInPlaneTolerance * farthestVertexDistance(x, polygon);
}

// Van Oosterom & Strackee's formula for the solid angle of the triangle a, b, c (seen from the
// origin): tan(Ω/2) = a·(b×c) / (|a||b||c| + (a·b)|c| + (a·c)|b| + (b·c)|a|). atan2 keeps the
// quadrant, so a triangle wider than π sr (negative denominator) comes out right, and the sign of
// the triple product says the winding.
double signedTriangleSolidAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
  const double numerator = glm::dot(a, glm::cross(b, c));
  const double denominator =
      la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
  return 2 * std::atan2(numerator, denominator);
}

// Twice the signed area (shoelace): positive when the vertices run counter-clockwise.
double twiceSignedArea(std::span<const glm::dvec2> polygon) {
  double sum = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2& p = polygon[i];
    const glm::dvec2& q = polygon[(i + 1) % polygon.size()];
    sum += p.x * q.y - p.y * q.x;
  }
  return sum;
}

double cross2(const glm::dvec2& a, const glm::dvec2& b) {
  return a.x * b.y - a.y * b.x;
}

// One Sutherland–Hodgman step: the part of `polygon` on the inner side of the line from `from`
// to `to`. `side` is +1 when the clip polygon runs counter-clockwise, −1 when clockwise, so that
// "inner" is the clip polygon's side of its edge whatever its winding.
std::vector<glm::dvec2> clipToHalfPlane(const std::vector<glm::dvec2>& polygon,
                                        const glm::dvec2& from, const glm::dvec2& to, double side) {
  std::vector<glm::dvec2> kept;
  const glm::dvec2 edge = to - from;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2& p = polygon[i];
    const glm::dvec2& q = polygon[(i + 1) % polygon.size()];
    const double dp = side * cross2(edge, p - from), dq = side * cross2(edge, q - from);
    if (dp >= 0) kept.push_back(p);
    // Strictly opposite sides: a vertex on the line is kept as itself, not as a crossing.
    if ((dp > 0 && dq < 0) || (dp < 0 && dq > 0)) kept.push_back(p + (q - p) * (dp / (dp - dq)));
  }
  return kept;
}

// The plane of a light: a point on it, its unit normal and two unit axes spanning it.
struct PlaneFrame {
  glm::dvec3 origin, normal, u, w;

  double heightOf(const glm::dvec3& p) const { return glm::dot(normal, p - origin); }
  glm::dvec2 toPlane(const glm::dvec3& p) const {
    return {glm::dot(p - origin, u), glm::dot(p - origin, w)};
  }
  glm::dvec3 fromPlane(const glm::dvec2& p) const { return origin + p.x * u + p.y * w; }
};

PlaneFrame frameOf(std::span<const glm::dvec3> light) {
  const glm::dvec3 normal = vectorArea(light);
  if (light.size() < 3 || glm::length(normal) == 0)
    throw std::invalid_argument("visibleSolidAngle: the light needs three vertices and an area");
  PlaneFrame frame;
  frame.origin = light[0];
  frame.normal = glm::normalize(normal);
  // Any axis not parallel to the normal gives a perpendicular one; the smaller the normal's
  // component along it, the better conditioned the cross product.
  const glm::dvec3 helper =
      std::abs(frame.normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  frame.u = glm::normalize(glm::cross(helper, frame.normal));
  frame.w = glm::cross(frame.normal, frame.u);
  return frame;
}

// The occluder's shadow on the light's plane, central projection from x (at signed height
// `x_height` over the plane), in the plane's 2D coordinates. A vertex strictly between x and the
// plane keeps the projection finite and on the far side of the occluder from x, which is what
// makes "the part of the light behind the occluder" this shadow.
std::vector<glm::dvec2> projectOccluder(const glm::dvec3& x, double x_height,
                                        const PlaneFrame& frame,
                                        std::span<const glm::dvec3> occluder) {
  std::vector<glm::dvec2> shadow;
  for (std::size_t i = 0; i < occluder.size(); ++i) {
    const double fraction = frame.heightOf(occluder[i]) / x_height;  // 1 at x, 0 on the light
    if (!(fraction > 0 && fraction < 1))
      throw std::invalid_argument("visibleSolidAngle: occluder vertex " + std::to_string(i) +
                                  " does not lie strictly between x and the light's plane");
    // x + t·(v − x) reaches the plane where its height x_height·(1 − t·(1 − fraction)) is 0.
    shadow.push_back(frame.toPlane(x + (occluder[i] - x) / (1 - fraction)));
  }
  return shadow;
}

std::vector<glm::dvec2> toPlane(const PlaneFrame& frame, std::span<const glm::dvec3> polygon) {
  std::vector<glm::dvec2> flat;
  for (const glm::dvec3& p : polygon) flat.push_back(frame.toPlane(p));
  return flat;
}

std::vector<glm::dvec3> fromPlane(const PlaneFrame& frame, std::span<const glm::dvec2> polygon) {
  std::vector<glm::dvec3> lifted;
  for (const glm::dvec2& p : polygon) lifted.push_back(frame.fromPlane(p));
  return lifted;
}

}  // namespace

double polygonSolidAngle(const glm::dvec3& x, std::span<const glm::dvec3> polygon) {
  if (polygon.size() < 3) return 0;
  const glm::dvec3 normal = vectorArea(polygon);
  if (glm::length(normal) == 0) return 0;
  // In the plane every triple product vanishes and atan2(±0, negative) would give ±π per
  // triangle: the limit from either side (2π inside the polygon) is not the answer there.
  if (liesInPlane(x, polygon, glm::dot(glm::normalize(normal), x - polygon[0]))) return 0;
  // A fan from vertex 0. Off the plane each triangle lies in an open hemisphere around x, so its
  // signed angle is exact, and for a simple polygon the parts of the fan outside it cancel.
  double sum = 0;
  const glm::dvec3 a = polygon[0] - x;
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
    sum += signedTriangleSolidAngle(a, polygon[i] - x, polygon[i + 1] - x);
  return std::abs(sum);
}

std::vector<glm::dvec2> clipConvexPolygon(std::span<const glm::dvec2> subject,
                                          std::span<const glm::dvec2> clip) {
  if (subject.size() < 3 || clip.size() < 3) return {};
  const double clip_area = twiceSignedArea(clip), subject_area = twiceSignedArea(subject);
  if (clip_area == 0 || subject_area == 0) return {};
  const double side = clip_area > 0 ? 1.0 : -1.0;
  std::vector<glm::dvec2> inside(subject.begin(), subject.end());
  for (std::size_t i = 0; i < clip.size() && !inside.empty(); ++i)
    inside = clipToHalfPlane(inside, clip[i], clip[(i + 1) % clip.size()], side);
  const double smaller = std::min(std::abs(clip_area), std::abs(subject_area));
  if (inside.size() < 3 || std::abs(twiceSignedArea(inside)) <= kSliverArea * smaller) return {};
  return inside;
}

double visibleSolidAngle(const glm::dvec3& x, std::span<const glm::dvec3> light,
                         std::span<const glm::dvec3> occluder) {
  const PlaneFrame frame = frameOf(light);
  const double x_height = frame.heightOf(x);
  if (liesInPlane(x, light, x_height))
    throw std::invalid_argument("visibleSolidAngle: x lies in the light's plane");
  const double unoccluded = polygonSolidAngle(x, light);
  // Past a convex occluder, x misses exactly the part of the light inside its shadow; both are
  // convex (central projection keeps convexity when the occluder is on one side of x's plane).
  const std::vector<glm::dvec2> shadow = projectOccluder(x, x_height, frame, occluder);
  const std::vector<glm::dvec2> hidden = clipConvexPolygon(toPlane(frame, light), shadow);
  if (hidden.empty()) return unoccluded;
  // The hidden part is inside the light, so rounding alone can take the difference below zero.
  return std::max(0.0, unoccluded - polygonSolidAngle(x, fromPlane(frame, hidden)));
}

}  // namespace gib::scene
