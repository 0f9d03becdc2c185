// What the shadow-map passes share between C++ and GLSL (binding points are in the binding plan:
// kShadowMapUnit, and the image units of the variance shadow map's filter).
#pragma once
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

// Work group side of vsm_blur.comp.glsl (square groups; cube maps add one layer per face).
const int kVsmBlurGroupSize = 8;

#ifdef __cplusplus
}  // namespace gib::rt::gpu
#endif
