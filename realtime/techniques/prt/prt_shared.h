// The PRT draw's storage buffers, read by prt_technique.cpp and prt.vert.glsl: per-vertex
// positions, cluster and CPCA weights, the corners of the sub-triangles (drawn as arrays, three
// per triangle, each naming its vertex), and the frame's projections L·M^k and L·B_d^k
// (book eq. 8.5), within the technique's range of the binding plan.
#pragma once
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

const int kPrtPositionsBinding = kTechniqueFirstStorageBinding + 0;  // vec4 per vertex, w unused
const int kPrtCornersBinding = kTechniqueFirstStorageBinding + 1;    // uint per triangle corner
const int kPrtClustersBinding = kTechniqueFirstStorageBinding + 2;   // uint per vertex
// float per vertex and basis vector: vertex v's weight d at v·M + d
const int kPrtWeightsBinding = kTechniqueFirstStorageBinding + 3;
// vec4 per cluster k and basis d = 0..M (0 the mean): the RGB dot product at k·(M + 1) + d
const int kPrtProjectionsBinding = kTechniqueFirstStorageBinding + 4;

#ifdef __cplusplus
static_assert(kPrtProjectionsBinding <
              kTechniqueFirstStorageBinding + kTechniqueStorageBindingCount);
}  // namespace gib::rt::gpu
#endif
