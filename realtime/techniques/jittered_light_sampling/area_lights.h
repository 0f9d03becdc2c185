// The scene's emissive triangles gathered into planar area lights, the unit jittered light
// sampling samples: a light is the triangles of one plane, facing one way, with one radiance, so
// that one coverage image (its window the light's bounding rectangle in that plane) samples it.
#pragma once

#include "realtime/gpu_scene/gpu_scene.h"

#include <glm/vec3.hpp>

#include <vector>

namespace gib::rt {

struct AreaLight {
  std::vector<glm::vec3> triangles;  // three corners each; the first gives the frame's axes
  glm::vec3 normal{0.0f};            // the side it emits to
  scene::Rgb emission{0.0f};         // radiance
};

// Triangles join a light when their normal, plane and radiance agree with its first triangle's
// to a relative 1e-4 of the scene's extent (the Cornell box's light: one light of two triangles).
std::vector<AreaLight> groupAreaLights(const std::vector<EmitterTriangle>& emitters, float extent);

}  // namespace gib::rt
