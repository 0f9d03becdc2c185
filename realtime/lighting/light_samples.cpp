#include "realtime/lighting/light_samples.h"

#include "scene/environment_distribution.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gib::rt {

gpu::GpuLightSample toGpuLightSample(const LightSample& s, const glm::mat4& view_projection) {
  const float w =
      s.kind == LightSampleKind::kDirectional ? s.cap_half_angle : s.distance_squared_offset;
  return {glm::vec4(s.position, w), glm::vec4(s.axis, s.cos_cone),
          glm::vec4(s.intensity.x, s.intensity.y, s.intensity.z, s.exponent), view_projection};
}

glm::vec2 hammersley(std::uint32_t i, std::uint32_t n) {
  // Base-2 radical inverse: the bits of i mirrored about the binary point.
  std::uint32_t bits = i;
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  return {(float(i) + 0.5f) / float(n), float(double(bits) * 0x1p-32)};
}

namespace {

void addAreaSamples(const std::vector<EmitterTriangle>& emitters, int count, float lift,
                    std::vector<LightSample>& out) {
  if (emitters.empty() || count <= 0) return;
  // Choose triangles in proportion to power (area × luminance), as the reference's NEE does.
  std::vector<double> cdf;
  double total = 0;
  for (const EmitterTriangle& e : emitters) {
    total += double(e.area) * double(scene::luminance(e.emission));
    cdf.push_back(total);
  }
  if (total <= 0) return;
  for (int i = 0; i < count; ++i) {
    const glm::vec2 u = hammersley(std::uint32_t(i), std::uint32_t(count));
    const double target = double(u.x) * total;
    const std::size_t t =
        std::min(std::size_t(std::upper_bound(cdf.begin(), cdf.end(), target) - cdf.begin()),
                 emitters.size() - 1);
    const double lower = t == 0 ? 0.0 : cdf[t - 1];
    const double probability = (cdf[t] - lower) / total;
    // Reuse the first coordinate within the chosen triangle, so the set stays stratified.
    const float s = float(std::clamp((target - lower) / (cdf[t] - lower), 0.0, 1.0));
    const float r = std::sqrt(s);  // uniform over the triangle (pbrt's square-root mapping)
    const EmitterTriangle& e = emitters[t];
    const glm::vec3 p = (1.0f - r) * e.a + r * (1.0f - u.y) * e.b + r * u.y * e.c;
    // pdf of the point: probability / area; the point stands for radiance · cosθ / pdf / count.
    LightSample sample;
    sample.kind = LightSampleKind::kPoint;
    sample.position = p + lift * e.normal;
    sample.axis = e.normal;
    sample.intensity = e.emission * float(double(e.area) / probability / double(count));
    sample.cos_cone = 0.0f;
    sample.exponent = 1.0f;
    out.push_back(sample);
  }
}

void addSkySamples(const scene::Rgb& radiance, int count, std::vector<LightSample>& out) {
  if (count <= 0 || scene::luminance(radiance) <= 0) return;
  // Uniform directions over the sphere: each carries radiance · 4π / count of irradiance.
  for (int i = 0; i < count; ++i) {
    const glm::vec2 u = hammersley(std::uint32_t(i), std::uint32_t(count));
    const float z = 1.0f - 2.0f * u.x;
    const float radius = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * std::numbers::pi_v<float> * u.y;
    const glm::vec3 towards_sky(radius * std::cos(phi), z, radius * std::sin(phi));
    LightSample sample;
    sample.kind = LightSampleKind::kDirectional;
    sample.axis = -towards_sky;
    sample.intensity = radiance * (4.0f * std::numbers::pi_v<float> / float(count));
    out.push_back(sample);
  }
}

// An environment map (book §4.2.3's decomposition of the sky into directional lights, here by
// importance rather than by cells): directions drawn by the map's luminance
// (scene/environment_distribution.h, the reference's own distribution) at Hammersley points, each
// carrying L(ω) / (pdf(ω) · count) of irradiance, an unbiased estimate of the map's light.
void addEnvironmentSamples(const scene::EnvironmentMap& map, int count,
                           std::vector<LightSample>& out) {
  if (count <= 0 || map.empty()) return;
  const scene::EnvironmentDistribution distribution(map);
  if (distribution.black()) return;
  for (int i = 0; i < count; ++i) {
    const scene::EnvironmentSample s =
        distribution.sample(hammersley(std::uint32_t(i), std::uint32_t(count)));
    if (s.pdf <= 0) continue;
    LightSample sample;
    sample.kind = LightSampleKind::kDirectional;
    sample.axis = -s.direction;
    sample.intensity = s.radiance / (s.pdf * float(count));
    out.push_back(sample);
  }
}

}  // namespace

std::vector<LightSample> makeLightSamples(const scene::Scene& scene,
                                          const std::vector<EmitterTriangle>& emitters,
                                          int area_samples, int sky_samples, float lift) {
  std::vector<LightSample> samples;
  for (const scene::SpotLight& spot : scene.spot_lights) {
    LightSample s;
    s.kind = LightSampleKind::kPoint;
    s.position = spot.position;
    s.axis = glm::normalize(spot.direction);
    s.intensity = spot.intensity;
    s.cos_cone = std::cos(glm::radians(spot.cone_angle_deg));
    s.exponent = spot.falloff_exponent;
    samples.push_back(s);
  }
  for (const scene::DirectionalLight& light : scene.directional_lights) {
    LightSample s;
    s.kind = LightSampleKind::kDirectional;
    s.axis = glm::normalize(light.direction);
    s.intensity = light.irradiance;
    samples.push_back(s);
  }
  addAreaSamples(emitters, area_samples, lift, samples);
  addSkySamples(scene.sky_radiance, sky_samples, samples);
  addEnvironmentSamples(scene.environment, sky_samples, samples);
  return samples;
}

}  // namespace gib::rt
