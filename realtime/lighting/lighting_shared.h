// What the shadow-map passes share between C++ and GLSL (binding points are in the binding plan:
// kShadowMapUnit, and the image units of the variance shadow map's filter).
#pragma once
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

// vsm_blur.comp.glsl: invocations per work group (neighbouring lines), and texels each invocation
// filters along its line.
const int kVsmBlurGroupSize = 64;
const int kVsmBlurSegment = 64;

#ifdef __cplusplus
}  // namespace gib::rt::gpu
#endif
