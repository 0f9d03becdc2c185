// The page of `gibench raycast-bench` (book Ch. 5 against Embree): per scene and kind of rays, a
// table of every structure's hit mismatches against Embree, rays per second, build time and
// memory, and per kind of rays a chart of rays per second against triangle count.
#pragma once

#include "metrics/timing_statistics.h"

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gib::reports {

struct RaycastStructureRow {
  std::string name;     // embree, brute_force, ray_engine, ray_engine_cones, loose_kd_tree, bvh
  std::string skipped;  // why it was not run here; empty when it ran
  std::size_t mismatches = 0, ties = 0;
  double max_abs_dt = 0, max_barycentric_error = 0;
  double mrays_per_second = 0;
  metrics::TimingSummary cast_ms;
  double build_ms = 0;
  std::optional<std::size_t> bytes;  // none: the structure does not report it
  // The ray engine with cones: the fraction of (tile, triangle) pairs its cones let through.
  std::optional<double> kept_pair_fraction;
};

struct RaycastCase {
  std::string scene;  // "chamber detail=3"
  std::string rays;   // primary, reflection, diffuse
  std::size_t triangles = 0, ray_count = 0, reference_hits = 0;
  double tie_distance = 0;
  std::vector<RaycastStructureRow> structures;
};

// The whole page; `facts` (program version, GL renderer, Embree, parameters) head it.
std::string raycastBenchPage(const std::vector<std::pair<std::string, std::string>>& facts,
                             const std::vector<RaycastCase>& cases);

}  // namespace gib::reports
