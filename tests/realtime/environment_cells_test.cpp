// The environment's cells (book §4.2.3, realtime/environment_cells/): their powers and solid
// angles add up to the map's, every texel is in one cell, the relaxation never raises its energy
// and keeps more, smaller cells where the map is bright; the centres' Delaunay mesh (incremental
// convex hull) has empty circumcircles and a sphere's Euler characteristic, also for duplicate
// and cocircular points; bad arguments are input errors.
#include "realtime/environment_cells/environment_cells.h"
#include "realtime/environment_cells/spherical_delaunay.h"

#include "common/input_error.h"
#include "scene/environment_map.h"
#include "scene/preetham_sky.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

namespace gib::rt {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kRows = 32;  // 32 × 64 maps: small, yet many texels per cell

// A map of radiance f(θ, φ) at each texel's centre (grey).
scene::EnvironmentMap mapOf(const std::function<float(double, double)>& f) {
  std::vector<float> texels;
  for (int y = 0; y < kRows; ++y)
    for (int x = 0; x < 2 * kRows; ++x) {
      const float v = f(kPi * (y + 0.5) / kRows, 2 * kPi * (x + 0.5) / (2 * kRows));
      texels.insert(texels.end(), {v, 0.5f * v, 0.25f * v + 0.01f});
    }
  return scene::makeEnvironmentMap(2 * kRows, kRows, std::move(texels), "test");
}

scene::EnvironmentMap patternedMap() {
  return mapOf([](double theta, double phi) {
    return float(1.0 + std::cos(3 * phi) * std::sin(theta) + (theta < 0.4 ? 20.0 : 0.0));
  });
}

TEST(EnvironmentCells, PowersAndSolidAnglesAddUpToTheMaps) {
  scene::EnvironmentMap map = patternedMap();
  map.intensity = 3.0f;
  map.rotation_deg = 40.0f;
  const EnvironmentCells cells = buildEnvironmentCells(map, 40, 8);
  ASSERT_EQ(cells.cells.size(), 40u);
  glm::dvec3 power(0.0);
  double solid_angle = 0;
  int texels = 0;
  for (const EnvironmentCell& cell : cells.cells) {
    power += glm::dvec3(cell.power);
    solid_angle += cell.solid_angle;
    texels += cell.texels;
  }
  const scene::Rgb integral = scene::environmentIntegral(map);
  // Float precision: the cells' sums and the integral are both in double, rounded to float.
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(power[c], integral[c], 1e-5 * integral[c]) << c;
  EXPECT_NEAR(solid_angle, 4 * kPi, 1e-9);
  // Every texel in exactly one cell: one index each, in range, and the counts add up.
  ASSERT_EQ(cells.texel_cell.size(), std::size_t(map.width * map.height));
  for (int cell : cells.texel_cell) ASSERT_TRUE(cell >= 0 && cell < 40);
  EXPECT_EQ(texels, map.width * map.height);
  // The world directions are the map directions turned by the map's rotation.
  for (std::size_t i = 0; i < cells.cells.size(); ++i)
    EXPECT_NEAR(glm::distance(glm::dvec3(map.toMap(cells.cells[i].direction)), cells.centres[i]),
                0.0, 1e-5);
}

TEST(EnvironmentCells, TexelsBelongToTheirNearestCentre) {
  // The grid search against brute force, at every texel.
  const scene::EnvironmentMap map = patternedMap();
  const EnvironmentCells cells = buildEnvironmentCells(map, 100, 3);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      const double theta = kPi * (y + 0.5) / map.height, phi = 2 * kPi * (x + 0.5) / map.width;
      const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::cos(theta),
                         std::sin(theta) * std::sin(phi));
      double best = -2;
      for (const glm::dvec3& c : cells.centres) best = std::max(best, glm::dot(d, c));
      const int cell = cells.texel_cell[std::size_t(y * map.width + x)];
      EXPECT_NEAR(glm::dot(d, cells.centres[std::size_t(cell)]), best, 1e-12) << x << ", " << y;
    }
}

TEST(EnvironmentCells, RelaxationNeverRaisesTheLloydEnergy) {
  scene::SkyParameters sky;
  sky.height = kRows;
  const scene::EnvironmentMap map = scene::makePreethamSky(sky);
  const EnvironmentCells cells = buildEnvironmentCells(map, 64, 12);
  ASSERT_EQ(cells.energies.size(), 13u);
  // Each step minimises the energy over the centres for the assignment, then over the
  // assignment for the centres: only rounding (relative 1e-12 of double sums) may raise it.
  for (std::size_t i = 1; i < cells.energies.size(); ++i)
    EXPECT_LE(cells.energies[i], cells.energies[i - 1] * (1 + 1e-12)) << "step " << i;
  EXPECT_LT(cells.energies.back(), cells.energies.front());
}

TEST(EnvironmentCells, ConstantMapGivesCellsOfNearlyEqualSolidAngle) {
  const scene::EnvironmentMap map = mapOf([](double, double) { return 1.0f; });
  constexpr int kCells = 16;
  const EnvironmentCells cells = buildEnvironmentCells(map, kCells, 32);
  // A relaxed Lloyd configuration of 16 points is not a regular polyhedron (none has 16
  // vertices): its Voronoi cells differ in area by some percent, and each cell is a union of
  // whole texels (up to 0.0096 sr each at the equator, about 1.2% of a cell, along a perimeter
  // of some 30 texels). 25% bounds both with a margin; a draw of 16 centres without relaxation
  // has no reason to meet it.
  for (const EnvironmentCell& cell : cells.cells)
    EXPECT_NEAR(cell.solid_angle, 4 * kPi / kCells, 0.25 * 4 * kPi / kCells);
}

TEST(EnvironmentCells, BrightRegionGetsMoreSmallerCells) {
  // 50 times brighter within 30° of the zenith: that cap holds 6.7% of the sphere and 78% of the
  // power, so equal-power cells put about three quarters of the centres in it.
  const scene::EnvironmentMap map =
      mapOf([](double theta, double) { return theta < kPi / 6 ? 50.0f : 1.0f; });
  constexpr int kCells = 64;
  const EnvironmentCells cells = buildEnvironmentCells(map, kCells, 8);
  int inside = 0;
  double inside_solid_angle = 0, outside_solid_angle = 0;
  for (std::size_t i = 0; i < cells.centres.size(); ++i) {
    if (cells.centres[i].y > std::cos(kPi / 6)) {
      ++inside;
      inside_solid_angle += cells.cells[i].solid_angle;
    } else {
      outside_solid_angle += cells.cells[i].solid_angle;
    }
  }
  ASSERT_GT(inside, 0);
  ASSERT_LT(inside, kCells);
  // Density: the cap's share of centres at least five times its share of the sphere (6.7%).
  const double cap_fraction = (1 - std::cos(kPi / 6)) / 2;
  EXPECT_GT(double(inside) / kCells, 5 * cap_fraction);
  // Size: the cap's cells at least five times smaller on average.
  EXPECT_LT(inside_solid_angle / inside, outside_solid_angle / (kCells - inside) / 5);
}

TEST(EnvironmentCells, BadArgumentsAreInputErrors) {
  const scene::EnvironmentMap map = patternedMap();
  EXPECT_THROW(buildEnvironmentCells(map, 0, 8), InputError);
  EXPECT_THROW(buildEnvironmentCells(map, map.width * map.height + 1, 0), InputError);
  EXPECT_NO_THROW(buildEnvironmentCells(map, map.width * map.height, 0));
  std::vector<float> zero(std::size_t(3 * 2 * kRows * kRows), 0.0f);
  EXPECT_THROW(
      buildEnvironmentCells(scene::makeEnvironmentMap(2 * kRows, kRows, zero, "black"), 4, 1),
      InputError);
  try {
    buildEnvironmentCells(map, 0, 8);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cells must be at least 1"), std::string::npos);
  }
}

// Every triangle's circumcircle is empty: no point lies on the outer side of its plane.
void expectDelaunay(const std::vector<glm::dvec3>& points, const SphericalDelaunay& mesh) {
  std::vector<bool> skipped(points.size(), false);
  for (int i : mesh.skipped) skipped[std::size_t(i)] = true;
  const std::size_t vertices = points.size() - mesh.skipped.size();
  // Euler: V − E + F = 2 with 3F = 2E gives F = 2V − 4.
  EXPECT_EQ(mesh.triangles.size(), 2 * vertices - 4);
  for (const auto& t : mesh.triangles)
    for (std::size_t p = 0; p < points.size(); ++p) {
      if (skipped[p] || int(p) == t[0] || int(p) == t[1] || int(p) == t[2]) continue;
      ASSERT_LE(orientation(points[std::size_t(t[0])], points[std::size_t(t[1])],
                            points[std::size_t(t[2])], points[p]),
                0)
          << "point " << p << " inside a circumcircle";
    }
}

TEST(SphericalDelaunay, RelaxedCentresHaveEmptyCircumcircles) {
  scene::SkyParameters sky;
  sky.height = kRows;
  const EnvironmentCells cells = buildEnvironmentCells(scene::makePreethamSky(sky), 200, 8);
  const SphericalDelaunay mesh = triangulateSphere(cells.centres);
  expectDelaunay(cells.centres, mesh);
}

TEST(SphericalDelaunay, DuplicateAndCocircularPointsAreHandled) {
  // A cube's corners (six cocircular quadruples) and the octahedron's vertices, then duplicates.
  std::vector<glm::dvec3> points;
  for (int i = 0; i < 8; ++i)
    points.push_back(glm::normalize(glm::dvec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1)));
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {-1.0, 1.0}) {
      glm::dvec3 p(0.0);
      p[axis] = sign;
      points.push_back(p);
    }
  points.push_back(points[3]);
  points.push_back(points[9]);
  const SphericalDelaunay mesh = triangulateSphere(points);
  EXPECT_EQ(mesh.skipped, (std::vector<int>{14, 15}));
  expectDelaunay(points, mesh);
  // Too few points, or all on one circle: no closed hull, no triangles.
  EXPECT_TRUE(triangulateSphere({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}).triangles.empty());
  EXPECT_TRUE(triangulateSphere({{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}}).triangles.empty());
}

TEST(EnvironmentCells, TriangulationImageMarksEdgesOnTheMap) {
  const scene::EnvironmentMap map = patternedMap();
  const EnvironmentCells cells = buildEnvironmentCells(map, 20, 4);
  const image::Image image = drawCellTriangulation(map, cells, triangulateSphere(cells.centres));
  ASSERT_EQ(image.width(), map.width);
  ASSERT_EQ(image.height(), map.height);
  int marked = 0;
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x)
      if (image.pixel(x, y)[1] > 0 && image.pixel(x, y)[0] == 0 && image.pixel(x, y)[2] == 0)
        ++marked;
  // 54 edges of some 0.5 rad, two points a texel: hundreds of green texels.
  EXPECT_GT(marked, 100);
}

}  // namespace
}  // namespace gib::rt
