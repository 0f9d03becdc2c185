// The ray engine of book §5.2–5.3 (RayEngine): the units of its rays, tile cones and triangle
// spheres (in the technique range: the engine is a pass of whoever runs it, binding_plan_shared.h),
// the storage binding its cone pass writes, and its work-group size.
#pragma once
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace gib::rt::gpu {
using glm::acos;
using glm::asin;
using glm::clamp;
using glm::dot;
using glm::length;
#endif

const int kRayEngineOriginsUnit = kTechniqueFirstUnit;         // RGBA32F 2D: origin, t_min
const int kRayEngineDirectionsUnit = kTechniqueFirstUnit + 1;  // RGBA32F 2D: direction, t_max
const int kRayEngineConesUnit = kTechniqueFirstUnit + 2;       // buffer: 2 texels per tile
const int kRayEngineSpheresUnit = kTechniqueFirstUnit + 3;  // buffer: centre, radius per triangle
const int kRayEngineConesBinding = kTechniqueFirstStorageBinding;
const int kRayEngineConeGroupSize = 64;

// A tile's cone record: texel 0 (apex, half angle φ), texel 1 (axis, mode): mode
// kConeCulls tests triangles against the cone, kConeKeepsAll lets every triangle through (rays
// more than a hemisphere apart, where no cone helps), kConeEmpty has no ray to cast.
const float kConeCulls = 1.0f;
const float kConeKeepsAll = 0.0f;
const float kConeEmpty = -1.0f;

// The book's test of §5.3: whether the triangle's bounding sphere (centre, radius) meets the
// tile's cone, φ + arcsin(r/|v − a|) ≥ arccos(x·(v − a)/|v − a|); true when the apex lies inside
// the sphere.
GIB_SHARED_FUNCTION bool sphereMeetsCone(vec4 sphere, vec4 apex_angle, vec4 axis_mode) {
  if (axis_mode.w == kConeEmpty) return false;
  if (axis_mode.w == kConeKeepsAll) return true;
  vec3 to_centre = vec3(sphere) - vec3(apex_angle);
  float distance = length(to_centre);
  if (distance <= sphere.w) return true;
  float deviation = acos(clamp(dot(vec3(axis_mode), to_centre) / distance, -1.0f, 1.0f));
  float sphere_angle = asin(sphere.w / distance);
  return apex_angle.w + sphere_angle >= deviation;
}

#ifdef __cplusplus
static_assert(kRayEngineSpheresUnit < kTechniqueFirstUnit + kTechniqueUnitCount);
}  // namespace gib::rt::gpu
#endif
