// Stochastic radiosity's GPU layout, read by its C++ and its GLSL: the selected shooter record of
// the Shooters buffer (written by the selection passes, read by visibility and update), binding
// points within the technique's ranges of the binding plan, and the compute passes' group sizes.
#pragma once
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

// std430, binding kShootersBinding: one selection.
struct Shooter {
  ivec2 texel;        // (−1, −1): nothing has power (Φ = 0)
  float power;        // lum(L_j)·A_j of the selected texel, as the selection saw it
  float total_power;  // Φ = Σ lum(L_i)·A_i
  float remaining;    // descent state: the selection value left within the current texel
  float u;            // the uniform random number in [0, 1) this selection was made with
  ivec2 padding;
};

const int kShootersBinding = kTechniqueFirstStorageBinding + 0;
// The first selection again, as a std140 uniform block (the same layout) for the passes that
// shoot from it: a uniform read costs llvmpipe one load for all lanes, a storage buffer read a
// load per lane.
const int kShooterBlockBinding = kTechniqueFirstUniformBinding + 0;

// Texture units.
const int kRadiositySourceUnit = kTechniqueFirstUnit + 0;     // L^e plus injected direct light
const int kRadiosityReflectedUnit = kTechniqueFirstUnit + 1;  // the reflected estimate L̃^r
const int kVisibilityUnit = kTechniqueFirstUnit + 2;          // the shooter's visibility map
const int kRadiosityPowerUnit = kTechniqueFirstUnit + 3;      // the power pyramid (the descent)

// Work groups: the power pyramid's square groups, the descent's one-dimensional ones.
const int kPyramidGroupSize = 8;
// Pyramid levels one pass writes (image units kImageDestinationUnit and the three after it): an
// invocation's 8×8 texels and the 4×4, 2×2 and 1×1 above them.
const int kPyramidLevelsPerPass = 4;
const int kDescentGroupSize = 64;

#ifdef __cplusplus
static_assert(sizeof(Shooter) == 32, "std430 struct Shooter");
static_assert(kRadiosityPowerUnit < kTechniqueFirstUnit + kTechniqueUnitCount);
static_assert(kShooterBlockBinding < kTechniqueFirstUniformBinding + kTechniqueUniformBindingCount);
}  // namespace gib::rt::gpu
#endif
