#include "realtime/environment_cells/spherical_delaunay.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

namespace gib::rt {

namespace {

struct Determinant {
  double value = 0;
  double bound = 0;  // what rounding can account for
};

// det[b − a, c − a, d − a] and a bound on its rounding error: each difference is off by up to
// half an ulp of the unit-length inputs (2⁻⁵³ each component), which moves the determinant by at
// most √3·2⁻⁵³ times the product of the other two lengths; the products and sums add a few ulps
// of the permanent (Shewchuk's orient3d filter, ≈ 7ε of it). Both with a factor of safety of 4.
Determinant orientationDeterminant(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                                   const glm::dvec3& d) {
  const glm::dvec3 u = b - a, v = c - a, w = d - a;
  const double vw_x = v.y * w.z - v.z * w.y, vw_y = v.z * w.x - v.x * w.z,
               vw_z = v.x * w.y - v.y * w.x;
  const double permanent = std::abs(u.x) * (std::abs(v.y * w.z) + std::abs(v.z * w.y)) +
                           std::abs(u.y) * (std::abs(v.z * w.x) + std::abs(v.x * w.z)) +
                           std::abs(u.z) * (std::abs(v.x * w.y) + std::abs(v.y * w.x));
  const double lu = glm::length(u), lv = glm::length(v), lw = glm::length(w);
  constexpr double kEpsilon = 0x1p-53;
  const double bound = 4.0 * (std::sqrt(3.0) * kEpsilon * (lv * lw + lu * lw + lu * lv) +
                              8.0 * kEpsilon * permanent);
  return {u.x * vw_x + u.y * vw_y + u.z * vw_z, bound};
}

int signOf(const Determinant& d) {
  if (d.value > d.bound) return 1;
  if (d.value < -d.bound) return -1;
  return 0;
}

// The hull under construction: faces counter-clockwise from outside, the live ones in a list
// (swap-removed), and each live face's directed edges in a map to find the face across an edge.
class Hull {
 public:
  explicit Hull(const std::vector<glm::dvec3>& points) : points_(points) {}

  void addFace(int a, int b, int c) {
    const int id = int(faces_.size());
    faces_.push_back({a, b, c});
    position_.push_back(int(live_.size()));
    live_.push_back(id);
    for (int k = 0; k < 3; ++k) {
      const auto [it, inserted] = edges_.emplace(key(faces_[id][k], faces_[id][(k + 1) % 3]), id);
      // A directed edge twice would make the surface non-manifold: the predicate disagreed with
      // itself, which the rounding bound is there to prevent.
      if (!inserted) throw std::logic_error("spherical Delaunay: a directed edge appears twice");
    }
  }

  // Inserts point p; false when no face sees it (it lies on the hull already).
  bool insert(int p) {
    std::vector<int> visible;
    for (int id : live_)
      if (orientation(points_[faces_[id][0]], points_[faces_[id][1]], points_[faces_[id][2]],
                      points_[p]) > 0)
        visible.push_back(id);
    if (visible.empty()) return false;
    std::unordered_map<int, bool> is_visible;
    for (int id : visible) is_visible[id] = true;
    // The horizon: edges of visible faces whose neighbour across them is not visible.
    std::vector<std::array<int, 2>> horizon;
    for (int id : visible)
      for (int k = 0; k < 3; ++k) {
        const int a = faces_[id][k], b = faces_[id][(k + 1) % 3];
        if (!is_visible.contains(edges_.at(key(b, a)))) horizon.push_back({a, b});
      }
    for (int id : visible) removeFace(id);
    for (const auto& [a, b] : horizon) addFace(a, b, p);
    return true;
  }

  std::vector<std::array<int, 3>> liveFaces() const {
    std::vector<std::array<int, 3>> out;
    for (int id : live_) out.push_back(faces_[id]);
    return out;
  }

 private:
  std::uint64_t key(int a, int b) const {
    return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
  }
  void removeFace(int id) {
    for (int k = 0; k < 3; ++k) edges_.erase(key(faces_[id][k], faces_[id][(k + 1) % 3]));
    const int slot = position_[id];
    live_[slot] = live_.back();
    position_[live_[slot]] = slot;
    live_.pop_back();
  }

  const std::vector<glm::dvec3>& points_;
  std::vector<std::array<int, 3>> faces_;
  std::vector<int> position_;  // each face's slot in live_ (stale once removed)
  std::vector<int> live_;
  std::unordered_map<std::uint64_t, int> edges_;
};

// Four points spanning a tetrahedron: the first, the farthest from it, the farthest from their
// line, the farthest from their plane (the last by its determinant, so only a set whose every
// point lies within rounding of one plane has none). Empty when there is no such four.
std::vector<int> initialTetrahedron(const std::vector<glm::dvec3>& points) {
  const int n = int(points.size());
  if (n < 4) return {};
  int i1 = -1, i2 = -1, i3 = -1;
  double best = 0;
  for (int i = 1; i < n; ++i)
    if (const double d = glm::length(points[i] - points[0]); d > best) best = d, i1 = i;
  if (i1 < 0) return {};
  best = 0;
  for (int i = 1; i < n; ++i)
    if (const double d = glm::length(glm::cross(points[i1] - points[0], points[i] - points[0]));
        d > best)
      best = d, i2 = i;
  if (i2 < 0) return {};
  best = 0;
  for (int i = 1; i < n; ++i) {
    const Determinant d = orientationDeterminant(points[0], points[i1], points[i2], points[i]);
    if (signOf(d) != 0 && std::abs(d.value) > best) best = std::abs(d.value), i3 = i;
  }
  if (i3 < 0) return {};
  return {0, i1, i2, i3};
}

}  // namespace

int orientation(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                const glm::dvec3& d) {
  return signOf(orientationDeterminant(a, b, c, d));
}

SphericalDelaunay triangulateSphere(const std::vector<glm::dvec3>& points) {
  SphericalDelaunay result;
  const std::vector<int> tetrahedron = initialTetrahedron(points);
  if (tetrahedron.empty()) return result;
  Hull hull(points);
  // Each face of the tetrahedron turned so that the fourth vertex lies on its inner side.
  for (int opposite = 0; opposite < 4; ++opposite) {
    std::array<int, 3> f;
    for (int k = 0, m = 0; k < 4; ++k)
      if (k != opposite) f[std::size_t(m++)] = tetrahedron[std::size_t(k)];
    if (orientation(points[f[0]], points[f[1]], points[f[2]],
                    points[tetrahedron[std::size_t(opposite)]]) > 0)
      std::swap(f[1], f[2]);
    hull.addFace(f[0], f[1], f[2]);
  }
  // Step by step: each further point deletes the faces it sees and closes the cavity.
  for (int i = 0; i < int(points.size()); ++i) {
    if (std::find(tetrahedron.begin(), tetrahedron.end(), i) != tetrahedron.end()) continue;
    if (!hull.insert(i)) result.skipped.push_back(i);
  }
  result.triangles = hull.liveFaces();
  return result;
}

}  // namespace gib::rt
