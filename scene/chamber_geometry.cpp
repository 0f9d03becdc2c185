#include "scene/chamber_geometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gib::scene::chamber {

namespace {

// a + (b − a)·k/n, exactly b at k = n, so that the patches that share an edge share its ends
// bit for bit.
double mix(double a, double b, int k, int n) {
  return k == n ? b : a + (b - a) * (double(k) / double(n));
}

glm::dvec3 mix(glm::dvec3 a, glm::dvec3 b, int k, int n) {
  return {mix(a.x, b.x, k, n), mix(a.y, b.y, k, n), mix(a.z, b.z, k, n)};
}

std::uint32_t addVertex(Mesh& mesh, glm::dvec3 p) {
  mesh.positions.emplace_back(float(p.x), float(p.y), float(p.z));
  return static_cast<std::uint32_t>(mesh.positions.size() - 1);
}

// Winds (a, b, c) so that its normal, computed from the stored float positions, points along
// facing(centroid).
void addFacingTriangle(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                       const PatchFacing& facing) {
  const glm::dvec3 pa(mesh.positions[a]), pb(mesh.positions[b]), pc(mesh.positions[c]);
  const glm::dvec3 normal = glm::cross(pb - pa, pc - pa);
  if (glm::dot(normal, facing((pa + pb + pc) / 3.0)) < 0) std::swap(b, c);
  mesh.triangles.push_back({a, b, c});
}

}  // namespace

glm::dvec2 unitCirclePoint(int i, int n) {
  // Reduce to the first octant by the circle's symmetries; negation is written 0.0 − v so that
  // a zero coordinate stays +0 (the scene hash sees the sign bit).
  if (i >= n) {
    const glm::dvec2 p = unitCirclePoint(i - n, n);
    return {0.0 - p.x, 0.0 - p.y};
  }
  if (2 * i == n) return {0.0, 1.0};
  if (2 * i > n) {
    const glm::dvec2 p = unitCirclePoint(n - i, n);
    return {0.0 - p.x, p.y};
  }
  if (n % 4 == 0 && 4 * i > n) {
    const glm::dvec2 p = unitCirclePoint(n / 2 - i, n);
    return {p.y, p.x};
  }
  if (i == 0) return {1.0, 0.0};
  const double angle = std::numbers::pi * double(i) / double(n);
  return {std::cos(angle), std::sin(angle)};
}

void appendPatch(Mesh& mesh, int nu, int nv, const PatchPoint& point, const PatchFacing& facing,
                 const PatchCells& leave_out) {
  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) addVertex(mesh, point(i, j));
  auto index = [&](int i, int j) { return base + std::uint32_t(j * (nu + 1) + i); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      if (leave_out && leave_out(i, j)) continue;
      addFacingTriangle(mesh, index(i, j), index(i + 1, j), index(i + 1, j + 1), facing);
      addFacingTriangle(mesh, index(i, j), index(i + 1, j + 1), index(i, j + 1), facing);
    }
}

void appendPanel(Mesh& mesh, glm::dvec3 corner, glm::dvec3 u, glm::dvec3 v, int nu, int nv,
                 glm::dvec3 facing) {
  appendPatch(
      mesh, nu, nv,
      [&](int i, int j) {
        return corner + (double(i) / double(nu)) * u + (double(j) / double(nv)) * v;
      },
      [&](glm::dvec3) { return facing; });
}

void appendBox(Mesh& mesh, glm::dvec3 lo, glm::dvec3 hi, int cells, bool with_bottom) {
  const glm::dvec3 dx(hi.x - lo.x, 0, 0), dy(0, hi.y - lo.y, 0), dz(0, 0, hi.z - lo.z);
  appendPanel(mesh, lo, dz, dy, cells, cells, {-1, 0, 0});
  appendPanel(mesh, lo + dx, dz, dy, cells, cells, {1, 0, 0});
  appendPanel(mesh, lo, dx, dy, cells, cells, {0, 0, -1});
  appendPanel(mesh, lo + dz, dx, dy, cells, cells, {0, 0, 1});
  appendPanel(mesh, lo + dy, dx, dz, cells, cells, {0, 1, 0});
  if (with_bottom) appendPanel(mesh, lo, dx, dz, cells, cells, {0, -1, 0});
}

void appendShaft(Mesh& mesh, glm::dvec3 base_centre, double radius, double height, int segments,
                 int rows) {
  appendPatch(
      mesh, segments, rows,
      [&](int i, int j) {
        const glm::dvec2 c = unitCirclePoint(2 * i, segments);
        return glm::dvec3(base_centre.x + radius * c.x,
                          mix(base_centre.y, base_centre.y + height, j, rows),
                          base_centre.z + radius * c.y);
      },
      [&](glm::dvec3 p) { return glm::dvec3(p.x - base_centre.x, 0, p.z - base_centre.z); });
}

void appendBarrelVault(Mesh& mesh, double spring_y, double radius, double z0, double z1,
                       int segments, int rows, const PatchCells& openings) {
  appendPatch(
      mesh, segments, rows,
      [&](int i, int j) {
        const glm::dvec2 c = unitCirclePoint(i, segments);
        return glm::dvec3(radius * c.x, spring_y + radius * c.y, mix(z0, z1, j, rows));
      },
      [&](glm::dvec3 p) { return glm::dvec3(-p.x, spring_y - p.y, 0); }, openings);
}

void appendLunette(Mesh& mesh, double z, double facing_z, double spring_y, double radius,
                   int segments, int rings) {
  const PatchFacing facing = [&](glm::dvec3) { return glm::dvec3(0, 0, facing_z); };
  auto ringPoint = [&](int i, int ring) {
    const glm::dvec2 c = unitCirclePoint(i, segments);
    const double r = mix(0.0, radius, ring, rings);
    return glm::dvec3(r * c.x, spring_y + r * c.y, z);
  };
  // A fan around the centre, then rings of quads out to the vault.
  const std::uint32_t centre = addVertex(mesh, {0, spring_y, z});
  const auto first = static_cast<std::uint32_t>(mesh.positions.size());
  for (int i = 0; i <= segments; ++i) addVertex(mesh, ringPoint(i, 1));
  for (int i = 0; i < segments; ++i)
    addFacingTriangle(mesh, centre, first + std::uint32_t(i), first + std::uint32_t(i + 1), facing);
  if (rings > 1)
    appendPatch(
        mesh, segments, rings - 1, [&](int i, int j) { return ringPoint(i, j + 1); }, facing);
}

void appendArchSoffit(Mesh& mesh, double x0, double x1, double centre_z, double spring_y,
                      double radius, int segments, int rows) {
  appendPatch(
      mesh, segments, rows,
      [&](int i, int j) {
        const glm::dvec2 c = unitCirclePoint(i, segments);
        return glm::dvec3(mix(x0, x1, j, rows), spring_y + radius * c.y, centre_z + radius * c.x);
      },
      [&](glm::dvec3 p) { return glm::dvec3(0, spring_y - p.y, centre_z - p.z); });
}

void appendSpandrel(Mesh& mesh, double x, double facing_x, double z0, double z1, double spring_y,
                    double top_y, double radius, int segments, int rows) {
  // The arch's segments are matched one to one with segments of the rectangle's outline (up the
  // z1 side, across the top, down the z0 side), shared out in proportion to the edges' lengths.
  const double height = top_y - spring_y;
  const double width = z1 - z0;
  const int side =
      std::clamp(int(std::lround(segments * height / (2 * height + width))), 1, (segments - 1) / 2);
  const int top = segments - 2 * side;
  const double centre_z = (z0 + z1) / 2;  // as appendArchSoffit computes it
  auto outline = [&](int i) {
    if (i <= side) return glm::dvec3(x, mix(spring_y, top_y, i, side), z1);
    if (i <= side + top) return glm::dvec3(x, top_y, mix(z1, z0, i - side, top));
    return glm::dvec3(x, mix(top_y, spring_y, i - side - top, side), z0);
  };
  appendPatch(
      mesh, segments, rows,
      [&](int i, int j) {
        const glm::dvec2 c = unitCirclePoint(i, segments);
        const glm::dvec3 arch(x, spring_y + radius * c.y, centre_z + radius * c.x);
        return mix(arch, outline(i), j, rows);
      },
      [&](glm::dvec3) { return glm::dvec3(facing_x, 0, 0); });
}

}  // namespace gib::scene::chamber
