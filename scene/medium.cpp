#include "scene/medium.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gib::scene {

namespace {

// Cells a particle's bounding cube spans per axis, on average. Small cells give tight majorants
// (few null collisions) and short particle lists; on the default cloud, 5 renders 6× faster than
// cells the size of a particle, and smaller cells gain little more.
constexpr double kCellsPerParticleSide = 5.0;
constexpr int kMaxResolution = 128;

}  // namespace

DensityGrid::DensityGrid(const std::vector<MediumParticle>& particles) : particles_(particles) {
  if (particles_.empty()) return;
  lower_ = glm::vec3(std::numeric_limits<float>::max());
  upper_ = glm::vec3(std::numeric_limits<float>::lowest());
  double volume_sum = 0;
  for (const MediumParticle& p : particles_) {
    lower_ = glm::min(lower_, p.centre - glm::vec3(p.radius));
    upper_ = glm::max(upper_, p.centre + glm::vec3(p.radius));
    volume_sum += 8.0 * double(p.radius) * p.radius * p.radius;  // bounding cube of the particle
  }
  // Cells of 1/kCellsPerParticleSide of the mean particle cube's side.
  const glm::vec3 extent = glm::max(upper_ - lower_, glm::vec3(1e-6f));
  const double mean_cube_side = std::cbrt(volume_sum / double(particles_.size()));
  const double side = std::max(mean_cube_side / kCellsPerParticleSide, 1e-12);
  for (int a = 0; a < 3; ++a) {
    resolution_[a] = std::clamp(int(std::ceil(extent[a] / side)), 1, kMaxResolution);
    cell_size_[a] = extent[a] / float(resolution_[a]);
  }

  // Bucket the particles by the cells their bounding cubes overlap (counting pass, then fill).
  const std::size_t cells = std::size_t(resolution_[0]) * resolution_[1] * resolution_[2];
  // A particle is listed in every cell its bounding cube touches, widened by a hair so that a
  // point on a cell boundary finds it whichever cell a lookup rounds to: then σt never exceeds
  // the majorant of the cell a tracker is in.
  auto cellRange = [&](const MediumParticle& p, glm::ivec3& lo, glm::ivec3& hi) {
    for (int a = 0; a < 3; ++a) {
      const float reach = p.radius + 1e-4f * cell_size_[a];
      lo[a] = std::clamp(int(std::floor((p.centre[a] - reach - lower_[a]) / cell_size_[a])), 0,
                         resolution_[a] - 1);
      hi[a] = std::clamp(int(std::floor((p.centre[a] + reach - lower_[a]) / cell_size_[a])), 0,
                         resolution_[a] - 1);
    }
  };
  // A particle's density inside a cell is at most τ·(1 − d/r), d the distance from its centre
  // to the cell's box: a far tighter bound than τ for particles that only graze the cell, so
  // trackers take fewer null collisions.
  auto densityBound = [&](const MediumParticle& p, int x, int y, int z) {
    const glm::vec3 box_lower = lower_ + glm::vec3(x, y, z) * cell_size_;
    const glm::vec3 nearest = glm::clamp(p.centre, box_lower, box_lower + cell_size_);
    const float d = glm::length(p.centre - nearest);
    // Rounded up by a hair, like the bucketing, so lookups near a boundary stay under it.
    return p.density * std::min(1.0f, std::max(0.0f, 1.0f - d / p.radius) + 1e-4f);
  };
  std::vector<std::uint32_t> counts(cells, 0);
  majorants_.assign(cells, 0.0f);
  for (const MediumParticle& p : particles_) {
    glm::ivec3 lo, hi;
    cellRange(p, lo, hi);
    for (int z = lo.z; z <= hi.z; ++z)
      for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x) {
          ++counts[cellIndex(x, y, z)];
          majorants_[cellIndex(x, y, z)] += densityBound(p, x, y, z);
        }
  }
  cell_start_.assign(cells + 1, 0);
  for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] = cell_start_[c] + counts[c];
  cell_particles_.resize(cell_start_[cells]);
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::uint32_t i = 0; i < particles_.size(); ++i) {
    glm::ivec3 lo, hi;
    cellRange(particles_[i], lo, hi);
    for (int z = lo.z; z <= hi.z; ++z)
      for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x) cell_particles_[fill[cellIndex(x, y, z)]++] = i;
  }
  max_majorant_ = *std::max_element(majorants_.begin(), majorants_.end());
}

float DensityGrid::density(const glm::vec3& p) const {
  if (particles_.empty()) return 0.0f;
  int cell[3];
  for (int a = 0; a < 3; ++a) {
    if (p[a] < lower_[a] || p[a] > upper_[a]) return 0.0f;
    cell[a] = std::min(int((p[a] - lower_[a]) / cell_size_[a]), resolution_[a] - 1);
  }
  const std::size_t c = cellIndex(cell[0], cell[1], cell[2]);
  float sigma = 0.0f;
  for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
    const MediumParticle& particle = particles_[cell_particles_[k]];
    const glm::vec3 d = p - particle.centre;
    const float d2 = glm::dot(d, d);
    if (d2 < particle.radius * particle.radius)
      sigma += particle.density * (1.0f - std::sqrt(d2) / particle.radius);
  }
  return sigma;
}

}  // namespace gib::scene
