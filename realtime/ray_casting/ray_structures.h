// The GPU ray-casting structures by name (book Ch. 5 and a modern BVH beside them), for the
// raycast bench and the techniques that cast rays (a `structure` parameter).
#pragma once

#include "realtime/ray_casting/gpu_ray_structure.h"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace gib::rt {

// The names makeGpuRayStructure takes, in table order.
const std::vector<std::string>& gpuRayStructureNames();

// Builds and uploads the structure of that name over the set (a GL context is current). Throws
// gib::InputError for an unknown name, listing the known ones.
std::unique_ptr<GpuRayStructure> makeGpuRayStructure(std::string_view name,
                                                     const IvmTriangleSet& set);

}  // namespace gib::rt
