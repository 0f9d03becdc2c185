// 3D-DDA through the density grid's cells (Amanatides & Woo), for MediumTracker::walkMajorants.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace gib::ref {

template <typename Visit>
void MediumTracker::walkMajorants(const glm::vec3& origin, const glm::vec3& direction, float t_max,
                                  Visit&& visit) const {
  if (grid_.empty()) return;
  constexpr float kInf = std::numeric_limits<float>::infinity();
  // Clip the segment to the grid's box (slab test).
  float t_enter = 0.0f, t_exit = t_max;
  const glm::vec3 lower = grid_.lower(), upper = grid_.upper();
  for (int a = 0; a < 3; ++a) {
    if (direction[a] == 0.0f) {
      if (origin[a] < lower[a] || origin[a] > upper[a]) return;
      continue;
    }
    float inv = 1.0f / direction[a];
    float t0 = (lower[a] - origin[a]) * inv, t1 = (upper[a] - origin[a]) * inv;
    if (t0 > t1) std::swap(t0, t1);
    t_enter = std::max(t_enter, t0);
    t_exit = std::min(t_exit, t1);
  }
  if (t_enter >= t_exit) return;

  // The starting cell and, per axis, the distance to the next cell boundary and between
  // boundaries.
  const auto& resolution = grid_.resolution();
  const glm::vec3 cell_size = grid_.cellSize();
  const glm::vec3 start = origin + t_enter * direction;
  int cell[3], step[3];
  float t_next[3], t_delta[3];
  for (int a = 0; a < 3; ++a) {
    cell[a] = std::clamp(int((start[a] - lower[a]) / cell_size[a]), 0, resolution[a] - 1);
    if (direction[a] > 0) {
      step[a] = 1;
      t_delta[a] = cell_size[a] / direction[a];
      t_next[a] =
          t_enter + (lower[a] + float(cell[a] + 1) * cell_size[a] - start[a]) / direction[a];
    } else if (direction[a] < 0) {
      step[a] = -1;
      t_delta[a] = -cell_size[a] / direction[a];
      t_next[a] = t_enter + (lower[a] + float(cell[a]) * cell_size[a] - start[a]) / direction[a];
    } else {
      step[a] = 0;
      t_delta[a] = kInf;
      t_next[a] = kInf;
    }
  }

  float t = t_enter;
  for (;;) {
    const int axis =
        (t_next[0] < t_next[1]) ? (t_next[0] < t_next[2] ? 0 : 2) : (t_next[1] < t_next[2] ? 1 : 2);
    const float t_end = std::min(t_next[axis], t_exit);
    if (t_end > t && !visit(t, t_end, grid_.majorant(cell[0], cell[1], cell[2]))) return;
    if (t_end >= t_exit) return;
    t = t_end;
    cell[axis] += step[axis];
    if (cell[axis] < 0 || cell[axis] >= resolution[axis]) return;
    t_next[axis] += t_delta[axis];
  }
}

}  // namespace gib::ref
