// The hemispherical gather's GPU layout, read by its C++ and its GLSL: texture units within the
// technique's range, the projections, and the work groups that sum a gather view.
#pragma once
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

const int kRadianceAtlasUnit = kTechniqueFirstUnit + 0;  // the directly lit scene: ρ/π·E per texel
const int kGatherViewsUnit = kTechniqueFirstUnit + 1;    // the batch's views, a layer each
const int kGatherIrradianceUnit = kTechniqueFirstUnit + 2;  // E at each gather point (grid)
const int kGBufferAlbedoUnit = kTechniqueFirstUnit + 3;     // the camera G-buffer's diffuse albedo

// How a gather view maps directions around the normal to its image (§5.2, Fig. 3).
const int kProjectionPerspective = 0;    // a 160° pinhole camera along the normal
const int kProjectionHemispherical = 1;  // fish-eye: the unit direction's tangent coordinates
const int kProjectionVoxelSlices = 2;    // fish-eye of the voxel slices, near objects drawn (§5.3)

// The voxel slices (§5.3): one array texture, layer face · slices + k for slab k, face 2·axis +
// side, side 0 the slab seen from its low side (looking along +axis), side 1 from its high side.
// The views' unit: the pass that draws slices and the pass that sums views never share a program.
const int kVoxelSlicesUnit = kTechniqueFirstUnit + 1;
const int kSliceFaces = 6;
// Clip distances of a gather view: the horizon, then the near box's six planes (voxel slices).
const int kGatherClipDistances = 7;

const float kPerspectiveFieldOfViewDegrees = 160.0f;
// tan(½ · 160°), the perspective view's half-width at unit distance, as a literal: GLSL's tan()
// may err by about 3·10⁻³ at 80° (the spec's derived bound), and the view's projection and the
// weights that sum its pixels must use one value on every driver (the float nearest the tangent,
// checked by tests/realtime/hemispherical_gather_test.cpp).
const float kPerspectiveHalfTangent = 5.67128181961771f;
const int kGatherSumGroupSize = 64;

#ifdef __cplusplus
static_assert(kGBufferAlbedoUnit < kTechniqueFirstUnit + kTechniqueUnitCount);
}  // namespace gib::rt::gpu
#endif
