#include "scene/environment_map.h"

#include "common/input_error.h"
#include "image/exr_io.h"

#include <fmt/format.h>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gib::scene {

namespace {

constexpr double kPi = std::numbers::pi;

// R_y(angle)·d: +x turns towards −z for a positive angle.
glm::vec3 rotateAboutY(const glm::vec3& d, float angle_deg) {
  if (angle_deg == 0.0f) return d;
  const float c = std::cos(glm::radians(angle_deg));
  const float s = std::sin(glm::radians(angle_deg));
  return {c * d.x + s * d.z, d.y, -s * d.x + c * d.z};
}

}  // namespace

Rgb EnvironmentMap::texel(int x, int y) const {
  const float* t = texels->data() + 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x));
  return {t[0], t[1], t[2]};
}

Rgb EnvironmentMap::radiance(const glm::vec3& world_direction) const {
  const glm::vec2 uv = latLongCoordinates(toMap(world_direction));
  const int x = std::min(int(uv.x * float(width)), width - 1);
  const int y = std::min(int(uv.y * float(height)), height - 1);
  return intensity * texel(x, y);
}

glm::vec3 EnvironmentMap::toMap(const glm::vec3& world_direction) const {
  return rotateAboutY(world_direction, -rotation_deg);
}

glm::vec3 EnvironmentMap::toWorld(const glm::vec3& map_direction) const {
  return rotateAboutY(map_direction, rotation_deg);
}

glm::vec2 latLongCoordinates(const glm::vec3& d) {
  const double length = std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z);
  // No direction (a zero or non-finite vector) has no place on the map: (0, 0), the zenith's first
  // texel, rather than NaN, which would make every texel index that follows undefined.
  if (!(length > 0) || !std::isfinite(length)) return {0.0f, 0.0f};
  const double theta = std::acos(std::clamp(double(d.y) / length, -1.0, 1.0));
  double phi = std::atan2(double(d.z), double(d.x));
  if (phi < 0) phi += 2 * kPi;
  // Rounding can give exactly 1 for φ just below 2π; the texel lookups clamp, the range stays.
  const float u = std::min(float(phi / (2 * kPi)), 0x1.fffffep-1f);
  const float v = std::min(float(theta / kPi), 0x1.fffffep-1f);
  return {u, v};
}

glm::vec3 latLongDirection(glm::vec2 uv) {
  const double phi = 2 * kPi * double(uv.x);
  const double theta = kPi * double(uv.y);
  const double sin_theta = std::sin(theta);
  return {float(sin_theta * std::cos(phi)), float(std::cos(theta)),
          float(sin_theta * std::sin(phi))};
}

EnvironmentMap makeEnvironmentMap(int width, int height, std::vector<float> texels,
                                  std::string source) {
  EnvironmentMap map;
  map.width = width;
  map.height = height;
  map.texels = std::make_shared<const std::vector<float>>(std::move(texels));
  map.source = std::move(source);
  validateEnvironmentMap(map);
  return map;
}

void validateEnvironmentMap(const EnvironmentMap& map) {
  if (map.height < 1 || map.width != 2 * map.height)
    throw InputError(fmt::format(
        "environment map is {}×{}, not a latitude–longitude map of width 2 × height; give an "
        "equirectangular image twice as wide as it is high",
        map.width, map.height));
  const std::size_t expected = 3 * std::size_t(map.width) * std::size_t(map.height);
  if (!map.texels || map.texels->size() != expected)
    throw InputError(fmt::format("environment map has {} values for {}×{} RGB texels ({})",
                                 map.texels ? map.texels->size() : 0, map.width, map.height,
                                 expected));
  const std::vector<float>& t = *map.texels;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (std::isfinite(t[i]) && t[i] >= 0) continue;
    const std::size_t texel = i / 3;
    throw InputError(fmt::format(
        "environment map texel ({}, {}) has {} value {}; radiance must be finite and >= 0 "
        "(clamp or repair the image)",
        texel % std::size_t(map.width), texel / std::size_t(map.width), "RGB"[i % 3], t[i]));
  }
  if (!std::isfinite(map.rotation_deg))
    throw InputError("environment rotation must be a finite angle in degrees");
  if (!std::isfinite(map.intensity) || map.intensity < 0)
    throw InputError(
        fmt::format("environment intensity {} must be finite and >= 0", map.intensity));
}

EnvironmentMap loadEnvironmentMap(const std::filesystem::path& exr_path) {
  const image::Image rgb = image::readRgb(exr_path);
  std::vector<float> texels(3 * rgb.pixelCount());
  for (int y = 0; y < rgb.height(); ++y)
    for (int x = 0; x < rgb.width(); ++x)
      for (int c = 0; c < 3; ++c)
        texels[3 * (std::size_t(y) * std::size_t(rgb.width()) + std::size_t(x)) + c] =
            rgb.pixel(x, y)[c];
  try {
    return makeEnvironmentMap(rgb.width(), rgb.height(), std::move(texels), exr_path.string());
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", exr_path.string(), e.what()));
  }
}

Rgb environmentIntegral(const EnvironmentMap& map) {
  glm::dvec3 sum(0.0);
  const double texel_phi = 2 * kPi / double(map.width);
  for (int y = 0; y < map.height; ++y) {
    const double solid_angle = texel_phi * (std::cos(kPi * double(y) / map.height) -
                                            std::cos(kPi * double(y + 1) / map.height));
    glm::dvec3 row(0.0);
    for (int x = 0; x < map.width; ++x) row += glm::dvec3(map.texel(x, y));
    sum += solid_angle * row;
  }
  return Rgb(sum * double(map.intensity));
}

}  // namespace gib::scene
