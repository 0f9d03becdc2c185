// Every light of the scene as a list of point and directional samples, each of which gets its own
// shadow map (book §4.1 for spot and directional lights; §4.2.3 for the sky, decomposed into
// directions; area lights by points on the emitters). With more samples the sum converges to the
// exact direct illumination, which is what makes `direct` comparable with the reference's LDE.
#pragma once

#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/lighting/light_sample_shared.h"
#include "scene/scene.h"

#include <vector>

namespace gib::rt {

enum class LightSampleKind { kPoint, kDirectional };

// A point sample emits intensity I(θ) = intensity · cos^exponent θ for cos θ ≥ cos_cone (θ from
// `axis`), zero outside: a spot light as given, and a point on a Lambertian emitter with
// exponent 1 and cos_cone 0. A directional sample delivers `intensity` as irradiance on a plane
// perpendicular to `axis`, the direction the light travels.
struct LightSample {
  LightSampleKind kind = LightSampleKind::kPoint;
  glm::vec3 position{0.0f};
  glm::vec3 axis{0.0f, -1.0f, 0.0f};
  scene::Rgb intensity{0.0f};
  float cos_cone = -1.0f;
  float exponent = 0.0f;
  // Added to the squared distance (light_irradiance.glsl): 0 but for a virtual light that stands
  // for a patch. The shading passes read samples as gpu::GpuLightSample (ShadowMaps uploads them).
  float distance_squared_offset = 0.0f;
  // A directional sample that stands for a cell of the environment (environment_shadows): the
  // half-angle of the cap of the cell's solid angle, radians; 0 for a light that is a direction.
  // Carried in GpuLightSample::position.w, which a directional sample does not otherwise read.
  float cap_half_angle = 0.0f;
};

// The sample as the shading passes read it (and pointSampleIrradiance takes it); a directional
// sample's shadow map's `view_projection` rides along.
gpu::GpuLightSample toGpuLightSample(const LightSample& sample,
                                     const glm::mat4& view_projection = glm::mat4(1.0f));

// Spot and directional lights one sample each; `area_samples` points over all emissive triangles
// (chosen in proportion to their power, stratified by a Hammersley set, each lifted off its
// emitter by `lift` along the normal so the emitter does not shadow itself); `sky_samples`
// directions over the sphere for a constant sky, or drawn by an environment map's luminance (its
// importance distribution) for a map. Deterministic: same scene, same samples.
std::vector<LightSample> makeLightSamples(const scene::Scene& scene,
                                          const std::vector<EmitterTriangle>& emitters,
                                          int area_samples, int sky_samples, float lift);

// Point i of an n-point Hammersley set in [0,1)²: (i + 0.5)/n and the base-2 radical inverse of i.
glm::vec2 hammersley(std::uint32_t i, std::uint32_t n);

}  // namespace gib::rt
