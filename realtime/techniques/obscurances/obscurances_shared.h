// Slots of the obscurances technique (book Ch. 10), declared once for C++ and GLSL.
#pragma once
#include "realtime/gl/binding_plan_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

// Σ over bundle rays of each patch's sample (rgb) and the number of rays (a), per atlas texel.
const int kObscuranceSumsUnit = kTechniqueFirstUnit + 0;
// Per atlas texel, the texel whose sums it shows (xy): itself inside a chart, the covered texel
// whose sample point a gutter texel copies (atlas_layout.h) in the gutter.
const int kObscuranceSourceUnit = kTechniqueFirstUnit + 1;
const int kObscuranceMapUnit = kTechniqueFirstUnit + 2;  // W per atlas texel (rgb)

#ifdef __cplusplus
static_assert(kObscuranceMapUnit < kTechniqueFirstUnit + kTechniqueUnitCount);
}  // namespace gib::rt::gpu
#endif
