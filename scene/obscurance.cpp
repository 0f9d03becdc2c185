#include "scene/obscurance.h"

#include "common/input_error.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace gib::scene {

namespace {

// The largest fraction of the scene's diagonal d_max may be: far beyond any scene's extent (a ray
// in the scene never runs longer than one diagonal), so every meaningful value fits, while a typo
// of a length in scene units (250 for 0.25) is caught.
constexpr float kMaxDistanceFraction = 100.0f;

// An albedo of 1 in a channel makes eq. 10.3's and 10.5's geometric series diverge; such a
// channel is taken as this (header: ambientLight).
constexpr float kMaxAverageAlbedo = 0.999f;

}  // namespace

std::string_view obscuranceFalloffName(ObscuranceFalloff falloff) {
  return falloff == ObscuranceFalloff::kAmbientOcclusion ? "ambient_occlusion" : "sqrt";
}

std::string_view obscuranceModeName(ObscuranceMode mode) {
  return mode == ObscuranceMode::kSpectral ? "spectral" : "scalar";
}

ObscuranceFalloff parseObscuranceFalloff(std::string_view name) {
  if (name == "sqrt") return ObscuranceFalloff::kSqrt;
  if (name == "ambient_occlusion") return ObscuranceFalloff::kAmbientOcclusion;
  throw InputError(fmt::format(
      "unknown obscurance fall-off '{}'; give sqrt (the book's rho(d) = sqrt(d/d_max)) or "
      "ambient_occlusion (a step at d_max)",
      name));
}

ObscuranceMode parseObscuranceMode(std::string_view name) {
  if (name == "scalar") return ObscuranceMode::kScalar;
  if (name == "spectral") return ObscuranceMode::kSpectral;
  throw InputError(fmt::format(
      "unknown obscurance mode '{}'; give scalar (grey W in [0, 1], eq. 10.2) or spectral "
      "(weighted by the albedo seen, eq. 10.4)",
      name));
}

void validateObscuranceDistanceFraction(float fraction) {
  if (!(std::isfinite(fraction) && fraction > 0 && fraction <= kMaxDistanceFraction))
    throw InputError(fmt::format(
        "d_max fraction {} is not in (0, {}]; give d_max as a fraction of the scene's bounding-box "
        "diagonal (default {})",
        fraction, kMaxDistanceFraction, ObscuranceDefinition::kDefaultObscuranceDistanceFraction));
}

std::string describeObscurance(const ObscuranceDefinition& d) {
  return fmt::format("obscurance({}, {}, d_max={})", obscuranceFalloffName(d.falloff),
                     obscuranceModeName(d.mode), d.d_max_fraction);
}

float sceneDiagonal(const Scene& scene) {
  glm::vec3 lo(std::numeric_limits<float>::max());
  glm::vec3 hi(std::numeric_limits<float>::lowest());
  for (const Mesh& mesh : scene.meshes)
    for (const glm::uvec3& triangle : mesh.triangles)
      for (int k = 0; k < 3; ++k) {
        lo = glm::min(lo, mesh.positions[triangle[k]]);
        hi = glm::max(hi, mesh.positions[triangle[k]]);
      }
  return lo.x <= hi.x ? glm::length(hi - lo) : 0.0f;
}

float maxDistance(const Scene& scene, const ObscuranceDefinition& definition) {
  return definition.d_max_fraction * sceneDiagonal(scene);
}

Rgb obscuranceAlbedo(const Material& material) {
  return isIdealSpecular(material.type) ? Rgb(0.0f) : material.diffuse;
}

SceneAverages sceneAverages(const Scene& scene) {
  // Sums in double: a scene of many small triangles would lose their areas in float.
  double area = 0;
  glm::dvec3 albedo(0.0), emitted(0.0);
  for (const Mesh& mesh : scene.meshes) {
    const Material& material = scene.materials.at(mesh.material);
    const glm::dvec3 a(obscuranceAlbedo(material));
    const glm::dvec3 emission(material.emission);
    for (const glm::uvec3& t : mesh.triangles) {
      const glm::dvec3 p0(mesh.positions[t[0]]), p1(mesh.positions[t[1]]), p2(mesh.positions[t[2]]);
      const double triangle_area = 0.5 * glm::length(glm::cross(p1 - p0, p2 - p0));
      area += triangle_area;
      albedo += triangle_area * a;
      emitted += triangle_area * emission;
    }
  }
  // A spot light of power Φ = I·∫cosᵏθ dω stands for a Lambertian emitter of the same power,
  // whose A·Lᵉ is Φ/π.
  for (const SpotLight& spot : scene.spot_lights)
    emitted += glm::dvec3(spot.intensity) * double(spotSolidAngleIntegral(spot)) / std::numbers::pi;
  SceneAverages averages;
  averages.area = area;
  if (area > 0) {
    averages.albedo = Rgb(albedo / area);
    averages.emitted_per_area = Rgb(emitted / area);
  }
  return averages;
}

Rgb ambientLight(const SceneAverages& averages, ObscuranceMode mode) {
  const Rgb a = glm::min(averages.albedo, Rgb(kMaxAverageAlbedo));
  // Scalar (eq. 10.3): the light after one, two, … reflections, ã L̃ᵉ + ã² L̃ᵉ + … The spectral
  // W already carries the first reflection's albedo, so its series starts one term earlier
  // (eq. 10.5).
  const Rgb series = Rgb(1.0f) / (Rgb(1.0f) - a);
  return mode == ObscuranceMode::kScalar ? a * series * averages.emitted_per_area
                                         : series * averages.emitted_per_area;
}

}  // namespace gib::scene
