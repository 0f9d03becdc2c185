// `environment_map` (book §4.2.1-4.2.2) as C++ and GLSL both read it: the technique's texture
// units and the convolution's work groups and limits.
#pragma once
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

// The convolved maps, a 2D array laid out as the environment (latitude-longitude, row 0 the
// zenith): layer 0 the irradiance E(n), layer 1 + k the glossy lobe's integral for the scene's
// k-th Phong exponent.
const int kConvolvedMapsUnit = kTechniqueFirstUnit + 0;
// The downsampled environment the convolution sums: rgb the mean radiance of each cell (before
// the map's intensity), and per cell xyz the integral of ω over it and w its solid angle.
const int kConvolutionRadianceUnit = kTechniqueFirstUnit + 1;
const int kConvolutionCellsUnit = kTechniqueFirstUnit + 2;
// The convolution's work groups: 8 × 8 texels of one layer.
const int kConvolutionGroupSize = 8;
// Distinct Phong exponents a scene may use, one glossy map each.
const int kMaxGlossyMaps = 8;

#ifdef __cplusplus
static_assert(kConvolutionCellsUnit < kTechniqueFirstUnit + kTechniqueUnitCount,
              "environment_map's textures stay inside the technique's units");
}  // namespace gib::rt::gpu
#endif
