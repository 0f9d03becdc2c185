// The irradiance volume's GPU layout, read by its C++ (irradiance_volume_technique.cpp,
// probe_grid.h) and its GLSL (irradiance_volume.glsl, sh_projection.comp.glsl): binding points
// within the technique's ranges of the binding plan, the coefficient buffer's layout and the
// arithmetic that places a probe's cube faces as tiles of one atlas.
#pragma once
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/host_device_shared.h"
#include "realtime/sh/spherical_harmonics_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

// Texture units.
const int kProbePositionUnit = kTechniqueFirstUnit + 0;  // the probe atlas's positions, w distance
const int kProbeRadianceUnit = kTechniqueFirstUnit + 1;  // the lit probe atlas, projected to SH
const int kProbeCoefficientsUnit = kTechniqueFirstUnit + 2;  // the coefficients, a buffer texture

// Storage buffers.
const int kProbeCoefficientsBinding = kTechniqueFirstStorageBinding + 0;  // vec4 per coefficient
const int kPhongFactorsBinding = kTechniqueFirstStorageBinding + 1;       // vec4 per material
const int kProjectionWeightsBinding = kTechniqueFirstStorageBinding + 2;  // float Y·dω per texel

// Work group of the SH projection: one group per probe reduces its six faces.
const int kShProjectionGroupSize = 64;

const int kCubeFaces = 6;

// Coefficient i of a probe in the coefficient buffer: a probe holds kShMaxCoefficients vec4s (rgb
// and an unused w), whatever the band in use.
GIB_SHARED_FUNCTION int probeCoefficientIndex(int probe, int i) {
  return probe * kShMaxCoefficients + i;
}

// The atlas tile of face `face` (0..5, GL's cube-face order) of a probe: six tiles per probe, in
// rows of `tiles_x`.
GIB_SHARED_FUNCTION int probeTile(int probe, int face) {
  return probe * kCubeFaces + face;
}

// The lower-left texel of a tile of `face_size`² texels.
GIB_SHARED_FUNCTION ivec2 tileOrigin(int tile, int tiles_x, int face_size) {
  return ivec2(tile % tiles_x, tile / tiles_x) * face_size;
}

#ifdef __cplusplus
static_assert(kProbeCoefficientsUnit < kTechniqueFirstUnit + kTechniqueUnitCount);
static_assert(kProjectionWeightsBinding <
              kTechniqueFirstStorageBinding + kTechniqueStorageBindingCount);
}  // namespace gib::rt::gpu
#endif
