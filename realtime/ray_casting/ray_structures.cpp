#include "realtime/ray_casting/ray_structures.h"

#include "common/input_error.h"
#include "realtime/ray_casting/bvh.h"
#include "realtime/ray_casting/loose_kd_tree.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace gib::rt {

const std::vector<std::string>& gpuRayStructureNames() {
  static const std::vector<std::string> names = {"brute_force", "loose_kd_tree", "bvh"};
  return names;
}

std::unique_ptr<GpuRayStructure> makeGpuRayStructure(std::string_view name,
                                                     const IvmTriangleSet& set) {
  if (name == "brute_force") return std::make_unique<GpuBruteForce>(set);
  if (name == "loose_kd_tree") return std::make_unique<GpuLooseKdTree>(set);
  if (name == "bvh") return std::make_unique<GpuBvh>(set);
  throw InputError(fmt::format("unknown ray-casting structure '{}'; give one of {}", name,
                               fmt::join(gpuRayStructureNames(), ", ")));
}

}  // namespace gib::rt
