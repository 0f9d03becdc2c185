// The illumination network's GPU layout (book §9.6.2, Fig. 9.19), read by its C++ and its GLSL:
// the visibility network's links, and the storage slots of its arrays. Each pass binds at most
// five buffers, so arrays that no pass reads together share a slot of the particle passes'
// (particle_shared.h): V and E (+2), J and the transmittance (+3).
#pragma once
#include "realtime/gl/host_device_shared.h"
#include "realtime/particles/particle_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

// V[p, i]: the particle p sees first in direction ω_i, and that particle's opacity along the
// line (its whole chord); particle −1: none, the sky.
struct NetworkLink {
  int particle;
  float opacity;
};

const int kVisibilityBinding = kTechniqueFirstStorageBinding + 2;  // NetworkLink[N × D]
const int kEmissionBinding = kTechniqueFirstStorageBinding + 2;    // vec4[N × D]
const int kSourceBinding = kTechniqueFirstStorageBinding + 3;      // vec4[N × D]
// W[d, i] = p(ω_d·ω_i) / Σ_d' p(ω_d'·ω_i), a D × D R32F texture: texel (i, d).
const int kPhaseMatrixUnit = kTechniqueFirstUnit + 1;
const int kMaxNetworkDirections = 1024;

// The incoming radiance I (vec4[N × D], w: the transmittance to the sky) is particle_shared.h's
// kIncomingRadianceBinding, where the view shading reads it.

#ifdef __cplusplus
static_assert(sizeof(NetworkLink) == 8, "std430 struct NetworkLink: int and float");
static_assert(kPhaseMatrixUnit < kTechniqueFirstUnit + kTechniqueUnitCount);
}  // namespace gib::rt::gpu
#endif
