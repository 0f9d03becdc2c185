// Participating media (docs/architecture.md, "Media"): a cloud of spherical particles, each with a
// centre, a radius and a density τ that falls off linearly, σt(p) = τ·(1 − d/r) for d < r.
// Overlapping particles add. The density field is defined here once and used by the reference path
// tracer and by the real-time techniques alike.
#pragma once

#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace gib::scene {

// Builds the lookup structure of a medium: a uniform grid over the particles' bounds, each cell
// listing the particles that overlap it and holding a majorant (an upper bound of σt inside the
// cell: the sum over those particles of their largest density within the cell). Grid resolution
// aims at a few particles per cell.
class DensityGrid {
 public:
  explicit DensityGrid(const std::vector<MediumParticle>& particles);

  bool empty() const { return particles_.empty(); }
  // Extinction coefficient σt at p (per scene unit).
  float density(const glm::vec3& p) const;
  // Upper bound of σt within cell (x, y, z).
  float majorant(int x, int y, int z) const { return majorants_[cellIndex(x, y, z)]; }
  float maxMajorant() const { return max_majorant_; }

  const glm::vec3& lower() const { return lower_; }
  const glm::vec3& upper() const { return upper_; }
  const std::array<int, 3>& resolution() const { return resolution_; }
  glm::vec3 cellSize() const { return cell_size_; }

 private:
  std::size_t cellIndex(int x, int y, int z) const {
    return (std::size_t(z) * resolution_[1] + std::size_t(y)) * resolution_[0] + std::size_t(x);
  }

  std::vector<MediumParticle> particles_;
  glm::vec3 lower_{0.0f}, upper_{0.0f}, cell_size_{1.0f};
  std::array<int, 3> resolution_{1, 1, 1};
  std::vector<std::uint32_t> cell_start_;  // per cell, offset into cell_particles_ (+1 end)
  std::vector<std::uint32_t> cell_particles_;
  std::vector<float> majorants_;
  float max_majorant_ = 0;
};

}  // namespace gib::scene
