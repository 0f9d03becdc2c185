// The batch pass of ray casting (RayCastPass, cast_rays.comp.glsl): its work-group size and the
// storage bindings of its rays and hits, in the range of whoever runs it (a technique's or the
// bench's own bindings, binding_plan_shared.h).
#pragma once
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

const int kCastGroupSize = 64;
const int kCastRaysBinding = kTechniqueFirstStorageBinding;
const int kCastHitsBinding = kTechniqueFirstStorageBinding + 1;

#ifdef __cplusplus
}  // namespace gib::rt::gpu
#endif
