// The size of the spherical-harmonic expansions the CPU tables (spherical_harmonics.h) and the
// GLSL basis (spherical_harmonics.glsl) agree on: bands 0..3, coefficient index l·l + l + m.
#pragma once
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

const int kShMaxBand = 3;
const int kShMaxCoefficients = (kShMaxBand + 1) * (kShMaxBand + 1);

// Coefficients of bands 0..`band`: 4 for band 1, 9 for band 2 (Nijasure et al.'s), 16 for band 3.
GIB_SHARED_FUNCTION int shCoefficientCount(int band) {
  return (band + 1) * (band + 1);
}

// The band of coefficient index i (l² ≤ i < (l+1)²).
GIB_SHARED_FUNCTION int shBand(int i) {
  return i < 1 ? 0 : i < 4 ? 1 : i < 9 ? 2 : 3;
}

#ifdef __cplusplus
}  // namespace gib::rt::gpu
#endif
