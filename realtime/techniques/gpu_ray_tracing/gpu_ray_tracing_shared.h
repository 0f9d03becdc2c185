// `gpu_ray_tracing`'s layouts, written once for C++ and GLSL (docs/architecture.md, "Declared GPU
// layouts"): the per-triangle record the trace pass reads at a hit, its unit, and the bounds of
// the ray tree.
#pragma once
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

// What a hit needs besides the structure's IVM (which names the triangle, not its material or
// normals): kTraceTriangleTexels RGBA32F texels per triangle of the IvmTriangleSet, in its order,
// as a buffer texture (llvmpipe gathers texel fetches across a SIMD row). Texel 0: the unit
// geometric normal (b − a) × (c − a) in xyz (the front side, which decides emission and the
// glass's inside), the material index in w (exact as a float up to 2²⁴); texels 1–3: the shading
// normals of vertices a, b, c, zero on a flat mesh.
const int kTraceTrianglesUnit = kTechniqueFirstUnit + 0;
const int kTraceTriangleTexels = 4;

// The deepest ray tree `max_depth` may ask for: the trace keeps one pending sibling per level in
// an array sized by it at compile time (MAX_DEPTH), so the bound is the shader's register budget.
const int kMaxTraceDepth = 12;

// A secondary ray leaves its surface this fraction of the scene's bounding-box diagonal along the
// geometric normal on its side, so that it does not hit its own triangle again: ten times
// Embree's 1e-5 (reference/embree_scene.cpp), since the IVM test computes t in single precision
// from the ray's origin relative to the triangle's apex, a few times less exact than Embree's.
const float kTraceRayOffsetFraction = 1.0e-4f;

#ifdef __cplusplus
static_assert(kTraceTrianglesUnit < kTechniqueFirstUnit + kTechniqueUnitCount,
              "gpu_ray_tracing's units stay inside the technique range");
}  // namespace gib::rt::gpu
#endif
