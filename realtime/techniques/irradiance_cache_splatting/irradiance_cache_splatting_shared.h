// Irradiance cache splatting's GPU layout, read by its C++ and its GLSL: the records' storage
// buffer, its texture units, the sampling kinds and the work groups that sum a record's views.
#pragma once
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

const int kRecordsBinding = kTechniqueFirstStorageBinding + 0;  // IrradianceRecord[]

const int kSplatRadianceAtlasUnit = kTechniqueFirstUnit + 0;  // the directly lit scene
const int kRecordViewsUnit = kTechniqueFirstUnit + 1;         // a round's views, a layer each
const int kSplatSumsUnit = kTechniqueFirstUnit + 2;           // Σ w·E (rgb) and Σ w (a)
const int kSplatAlbedoUnit = kTechniqueFirstUnit + 3;         // the G-buffer's diffuse albedo

// How a record's hemisphere is rasterized (notes 001, "From ray tracing to rasterization").
const int kRecordSamplingPlane = 0;     // one wide camera along the normal, borders extended
const int kRecordSamplingHemicube = 1;  // five 90° faces; the side faces' lower halves clipped
const int kMaxRecordFaces = 5;

// A record's sums: irradiance (3), harmonic-mean weights (2), rotation and translation gradients
// (9 each).
const int kRecordSums = 23;
const int kRecordSumGroupSize = 64;

#ifdef __cplusplus
static_assert(kRecordsBinding < kTechniqueFirstStorageBinding + kTechniqueStorageBindingCount);
static_assert(kSplatAlbedoUnit < kTechniqueFirstUnit + kTechniqueUnitCount);
}  // namespace gib::rt::gpu
#endif
