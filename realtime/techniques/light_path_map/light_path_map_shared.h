// The light path map's GPU layout, read by its C++ and its GLSL: the selected panes of a frame
// (written by the CPU after it has weighed the clusters, read by the combination pass) and the
// texture units within the technique's range of the binding plan.
#pragma once
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

// std430, binding kSelectedPanesBinding: one of the frame's highest-weighted clusters.
struct SelectedPane {
  vec3 weight;  // the cluster's mean entry irradiance, divided by the entry point count
  int layer;    // its pane in the pane array
};

const int kSelectedPanesBinding = kTechniqueFirstStorageBinding + 0;

// Texture units.
const int kEntryPositionUnit = kTechniqueFirstUnit + 0;  // xyz entry point, w 1 where there is one
const int kEntryNormalUnit = kTechniqueFirstUnit + 1;    // xyz its unit normal
const int kPanesUnit = kTechniqueFirstUnit + 2;          // the clusters' panes, one layer each
const int kIndirectUnit = kTechniqueFirstUnit + 3;       // the indirect atlas

#ifdef __cplusplus
static_assert(sizeof(SelectedPane) == 16, "std430 struct SelectedPane");
static_assert(kIndirectUnit < kTechniqueFirstUnit + kTechniqueUnitCount);
}  // namespace gib::rt::gpu
#endif
