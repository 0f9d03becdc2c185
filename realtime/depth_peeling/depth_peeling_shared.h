// The record depth peeling stores per pixel and layer (book §10.4), written once for the peeler
// (C++), its shaders and the passes that read the layers (the obscurances' bundle estimate, later
// the multi-layer refraction of Ch. 6): the patch address (the atlas coordinate of the surface
// point the pixel's ray crosses), whether that surface faces the bundle's origin, and its depth.
#pragma once
#include "realtime/gl/binding_plan_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

// A layer texel is vec4(atlas u, atlas v, facing, depth): facing is kPeelFrontFacing where the
// surface's geometric normal points back along the bundle (towards the projection plane),
// kPeelBackFacing where it points along it, and kPeelEmpty where the ray crosses no further
// surface; depth is the distance along the bundle from the projection plane, in scene units.
const float kPeelFrontFacing = 1.0f;
const float kPeelBackFacing = -1.0f;
const float kPeelEmpty = 0.0f;

// The previous-depth map of an empty pixel: beyond every surface, so the next layer peels nothing
// there.
const float kPeelBeyondEverything = 3.0e38f;

#ifdef __cplusplus
}  // namespace gib::rt::gpu
#endif
