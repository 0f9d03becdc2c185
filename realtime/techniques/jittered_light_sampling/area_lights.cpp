#include "realtime/techniques/jittered_light_sampling/area_lights.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace gib::rt {

namespace {

bool sameLight(const AreaLight& light, const EmitterTriangle& t, float tolerance) {
  const glm::vec3& p0 = light.triangles.front();
  return glm::dot(light.normal, t.normal) > 1.0f - 1e-4f &&
         std::abs(glm::dot(t.a - p0, light.normal)) < tolerance &&
         glm::length(light.emission - t.emission) <= 1e-4f * glm::length(light.emission);
}

}  // namespace

std::vector<AreaLight> groupAreaLights(const std::vector<EmitterTriangle>& emitters, float extent) {
  std::vector<AreaLight> lights;
  const float tolerance = 1e-4f * extent;
  for (const EmitterTriangle& t : emitters) {
    AreaLight* home = nullptr;
    for (AreaLight& light : lights)
      if (sameLight(light, t, tolerance)) home = &light;
    if (!home) {
      lights.push_back({{}, t.normal, t.emission});
      home = &lights.back();
    }
    home->triangles.insert(home->triangles.end(), {t.a, t.b, t.c});
  }
  return lights;
}

}  // namespace gib::rt
