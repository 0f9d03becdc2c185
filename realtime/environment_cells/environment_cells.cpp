#include "realtime/environment_cells/environment_cells.h"

#include "common/elapsed.h"
#include "common/input_error.h"
#include "realtime/lighting/light_samples.h"
#include "scene/environment_distribution.h"
#include "scene/scene.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

namespace gib::rt {

namespace {

constexpr double kPi = std::numbers::pi;

// The texels as the cells see them: unit map direction of the centre, solid angle, radiance
// (intensity included) and relaxation weight.
struct Texels {
  int width = 0, height = 0;
  std::vector<glm::dvec3> direction;
  std::vector<double> solid_angle, weight;
  std::vector<glm::dvec3> radiance;
};

Texels readTexels(const scene::EnvironmentMap& map) {
  Texels t;
  t.width = map.width;
  t.height = map.height;
  const std::size_t n = std::size_t(map.width) * std::size_t(map.height);
  t.direction.reserve(n);
  t.solid_angle.reserve(n);
  t.weight.reserve(n);
  t.radiance.reserve(n);
  for (int y = 0; y < map.height; ++y) {
    const double theta = kPi * (y + 0.5) / map.height;
    // Exactly the solid angle environmentIntegral gives each texel of the row.
    const double solid_angle =
        2 * kPi / map.width *
        (std::cos(kPi * y / map.height) - std::cos(kPi * (y + 1) / map.height));
    for (int x = 0; x < map.width; ++x) {
      const double phi = 2 * kPi * (x + 0.5) / map.width;
      t.direction.push_back(
          {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)});
      t.solid_angle.push_back(solid_angle);
      const glm::dvec3 radiance = glm::dvec3(map.texel(x, y)) * double(map.intensity);
      t.radiance.push_back(radiance);
      t.weight.push_back(relaxationWeight(scene::luminance(scene::Rgb(radiance)), solid_angle));
    }
  }
  return t;
}

// Nearest-centre search through a coarse grid of blocks of texels: a block's candidates are the
// centres within d + 2r of its middle direction m (d: m's nearest centre, r: the block's radius
// around m), since a texel t of the block has a centre within d + r of it and any centre that
// near lies within d + 2r of m (triangle inequality of angles). Blocks are about twice as many as
// centres, so each texel compares a handful of centres, not all of them.
class NearestCentre {
 public:
  NearestCentre(const Texels& texels, int cells) : texels_(texels) {
    const int n = texels.width * texels.height;
    side_ = std::max(1, int(std::sqrt(double(n) / (2.0 * cells))));
    columns_ = (texels.width + side_ - 1) / side_;
    rows_ = (texels.height + side_ - 1) / side_;
    for (int by = 0; by < rows_; ++by)
      for (int bx = 0; bx < columns_; ++bx) {
        glm::dvec3 sum(0.0);
        forTexels(bx, by, [&](int t) { sum += texels.direction[std::size_t(t)]; });
        // A block around a pole can sum to almost nothing: any of its texels serves as middle.
        const glm::dvec3 middle =
            glm::length(sum) > 1e-9
                ? glm::normalize(sum)
                : texels.direction[std::size_t(by * side_ * texels.width + bx * side_)];
        double min_dot = 1;
        forTexels(bx, by, [&](int t) {
          min_dot = std::min(min_dot, glm::dot(middle, texels.direction[std::size_t(t)]));
        });
        middle_.push_back(middle);
        radius_.push_back(std::acos(std::clamp(min_dot, -1.0, 1.0)));
      }
  }

  // The nearest centre of every texel (ties to the lower index).
  void assign(const std::vector<glm::dvec3>& centres, std::vector<int>& texel_cell) const {
    std::vector<int> candidates;
    for (int by = 0; by < rows_; ++by)
      for (int bx = 0; bx < columns_; ++bx) {
        const std::size_t b = std::size_t(by * columns_ + bx);
        double best = -2;
        for (const glm::dvec3& c : centres) best = std::max(best, glm::dot(middle_[b], c));
        // A margin of 1e-9 rad for the rounding of acos and the dot products.
        const double reach = std::acos(std::clamp(best, -1.0, 1.0)) + 2 * radius_[b] + 1e-9;
        const double min_dot = reach >= kPi ? -2.0 : std::cos(reach);
        candidates.clear();
        for (int i = 0; i < int(centres.size()); ++i)
          if (glm::dot(middle_[b], centres[std::size_t(i)]) >= min_dot) candidates.push_back(i);
        forTexels(bx, by, [&](int t) {
          const glm::dvec3& d = texels_.direction[std::size_t(t)];
          int nearest = candidates.front();
          double nearest_dot = -2;
          for (int i : candidates)
            if (const double dot = glm::dot(d, centres[std::size_t(i)]); dot > nearest_dot)
              nearest_dot = dot, nearest = i;
          texel_cell[std::size_t(t)] = nearest;
        });
      }
  }

 private:
  template <typename F>
  void forTexels(int bx, int by, F&& f) const {
    for (int y = by * side_; y < std::min(texels_.height, (by + 1) * side_); ++y)
      for (int x = bx * side_; x < std::min(texels_.width, (bx + 1) * side_); ++x)
        f(y * texels_.width + x);
  }

  const Texels& texels_;
  int side_ = 1, columns_ = 0, rows_ = 0;
  std::vector<glm::dvec3> middle_;
  std::vector<double> radius_;
};

double lloydEnergy(const Texels& texels, const std::vector<glm::dvec3>& centres,
                   const std::vector<int>& texel_cell) {
  double energy = 0;
  for (std::size_t t = 0; t < texel_cell.size(); ++t)
    energy += texels.weight[t] *
              (2.0 - 2.0 * glm::dot(texels.direction[t], centres[std::size_t(texel_cell[t])]));
  return energy;
}

// Each centre to the weighted centroid of its cell projected onto the sphere, the unit c that
// minimises Σ w·|d − c|² over the cell; a cell without weight (no texel, or black ones) or whose
// centroid is the origin keeps its centre.
void moveCentres(const Texels& texels, const std::vector<int>& texel_cell,
                 std::vector<glm::dvec3>& centres) {
  std::vector<glm::dvec3> sums(centres.size(), glm::dvec3(0.0));
  std::vector<double> weights(centres.size(), 0.0);
  for (std::size_t t = 0; t < texel_cell.size(); ++t) {
    sums[std::size_t(texel_cell[t])] += texels.weight[t] * texels.direction[t];
    weights[std::size_t(texel_cell[t])] += texels.weight[t];
  }
  for (std::size_t i = 0; i < centres.size(); ++i)
    if (weights[i] > 0 && glm::length(sums[i]) > 1e-12 * weights[i])
      centres[i] = glm::normalize(sums[i]);
}

void checkArguments(const scene::EnvironmentMap& map, int cells, int relaxation_steps) {
  if (cells < 1)
    throw InputError(fmt::format(
        "cells must be at least 1; got {}: give the environment at least one cell", cells));
  const long long texels = (long long)map.width * map.height;
  if (cells > texels)
    throw InputError(fmt::format(
        "cells = {} exceeds the environment map's {} texels ({}×{}); use at most {} cells or a "
        "larger map",
        cells, texels, map.width, map.height, texels));
  if (relaxation_steps < 0)
    throw InputError(fmt::format("relaxation_steps must be at least 0; got {}", relaxation_steps));
}

}  // namespace

double relaxationWeight(double luminance, double solid_angle) {
  return luminance * luminance * solid_angle;
}

double capHalfAngle(double solid_angle) {
  // Δω = 2π(1 − cos α).
  return std::acos(std::clamp(1.0 - solid_angle / (2 * kPi), -1.0, 1.0));
}

EnvironmentCells buildEnvironmentCells(const scene::EnvironmentMap& map, int cells,
                                       int relaxation_steps) {
  checkArguments(map, cells, relaxation_steps);
  const auto start = std::chrono::steady_clock::now();
  const scene::EnvironmentDistribution distribution(map);
  if (distribution.black())
    throw InputError(fmt::format(
        "the environment map '{}' is black: it has no light to divide into cells; give it a "
        "map with radiance",
        map.source));
  EnvironmentCells out;
  // Step 1: centres drawn in proportion to radiance, at the points of a Hammersley set (a fixed
  // low-discrepancy set: the same map gives the same centres).
  for (int i = 0; i < cells; ++i) {
    const scene::EnvironmentSample s =
        distribution.sample(hammersley(std::uint32_t(i), std::uint32_t(cells)));
    out.centres.push_back(glm::normalize(glm::dvec3(map.toMap(s.direction))));
  }
  const Texels texels = readTexels(map);
  const NearestCentre nearest(texels, cells);
  out.texel_cell.assign(texels.direction.size(), 0);
  // Step 2: weighted Lloyd relaxation, each step reassigning the texels and moving the centres.
  const auto relaxation_start = std::chrono::steady_clock::now();
  nearest.assign(out.centres, out.texel_cell);
  out.energies.push_back(lloydEnergy(texels, out.centres, out.texel_cell));
  for (int step = 0; step < relaxation_steps; ++step) {
    moveCentres(texels, out.texel_cell, out.centres);
    nearest.assign(out.centres, out.texel_cell);
    out.energies.push_back(lloydEnergy(texels, out.centres, out.texel_cell));
  }
  out.relaxation_ms = millisecondsSince(relaxation_start);
  // Step 3: each cell's power and solid angle, summed over its texels.
  std::vector<glm::dvec3> power(std::size_t(cells), glm::dvec3(0.0));
  out.cells.resize(std::size_t(cells));
  for (std::size_t t = 0; t < out.texel_cell.size(); ++t) {
    EnvironmentCell& cell = out.cells[std::size_t(out.texel_cell[t])];
    power[std::size_t(out.texel_cell[t])] += texels.radiance[t] * texels.solid_angle[t];
    cell.solid_angle += texels.solid_angle[t];
    ++cell.texels;
  }
  for (std::size_t i = 0; i < out.cells.size(); ++i) {
    out.cells[i].power = scene::Rgb(power[i]);
    out.cells[i].direction = glm::normalize(map.toWorld(glm::vec3(out.centres[i])));
  }
  out.total_ms = millisecondsSince(start);
  return out;
}

image::Image drawCellTriangulation(const scene::EnvironmentMap& map, const EnvironmentCells& cells,
                                   const SphericalDelaunay& triangulation) {
  image::Image image(map.width, map.height);
  double luminance_sum = 0;
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      const scene::Rgb radiance = map.texel(x, y) * map.intensity;
      float* p = image.pixel(x, y);
      p[0] = radiance.x, p[1] = radiance.y, p[2] = radiance.z;
      luminance_sum += scene::luminance(radiance);
    }
  const float mark = float(4.0 * luminance_sum / double(image.pixelCount()));
  const auto paint = [&](const glm::dvec3& d, const scene::Rgb& colour) {
    const glm::vec2 uv = scene::latLongCoordinates(glm::vec3(d));
    const int x = std::min(int(uv.x * float(map.width)), map.width - 1);
    const int y = std::min(int(uv.y * float(map.height)), map.height - 1);
    float* p = image.pixel(x, y);
    p[0] = colour.x, p[1] = colour.y, p[2] = colour.z;
  };
  // Each edge once (from its lower vertex), along the great circle, at about two points a texel.
  for (const auto& triangle : triangulation.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = triangle[std::size_t(k)], b = triangle[std::size_t((k + 1) % 3)];
      if (a > b) continue;
      const glm::dvec3 pa = cells.centres[std::size_t(a)], pb = cells.centres[std::size_t(b)];
      const double angle = std::acos(std::clamp(glm::dot(pa, pb), -1.0, 1.0));
      const int steps = std::max(2, int(2.0 * angle / kPi * map.height) + 1);
      for (int s = 0; s <= steps; ++s) {
        const double f = double(s) / steps;
        // Spherical linear interpolation; near-coincident ends fall back to the chord.
        const double sin_angle = std::sin(angle);
        const glm::dvec3 d =
            sin_angle > 1e-9
                ? (std::sin((1 - f) * angle) * pa + std::sin(f * angle) * pb) / sin_angle
                : (1 - f) * pa + f * pb;
        paint(d, {0.0f, mark, 0.0f});
      }
    }
  for (const glm::dvec3& c : cells.centres) paint(c, {mark, 0.0f, 0.0f});
  return image;
}

}  // namespace gib::rt
