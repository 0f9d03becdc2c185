#include "scene/environment_distribution.h"

#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gib::scene {

namespace {

constexpr double kPi = std::numbers::pi;

double rowSinTheta(int y, int height) {
  return std::sin(kPi * (double(y) + 0.5) / double(height));
}

}  // namespace

EnvironmentDistribution::EnvironmentDistribution(const EnvironmentMap& map) : map_(map) {
  const int w = map.width, h = map.height;
  row_cdf_.assign(std::size_t(h) + 1, 0.0);
  column_cdf_.assign(std::size_t(h) * (std::size_t(w) + 1), 0.0);
  for (int y = 0; y < h; ++y) {
    const double sin_theta = rowSinTheta(y, h);
    double* cdf = column_cdf_.data() + std::size_t(y) * (std::size_t(w) + 1);
    for (int x = 0; x < w; ++x)
      cdf[x + 1] = cdf[x] + double(luminance(map.texel(x, y))) * sin_theta;
    row_cdf_[std::size_t(y) + 1] = row_cdf_[std::size_t(y)] + cdf[w];
  }
  total_ = row_cdf_.back();
}

int EnvironmentDistribution::findInterval(std::span<const double> cdf, double target) {
  // The last i with cdf[i] <= target, skipping empty intervals (cdf[i] == cdf[i + 1]).
  const auto it = std::upper_bound(cdf.begin(), cdf.end(), target);
  return std::clamp(int(it - cdf.begin()) - 1, 0, int(cdf.size()) - 2);
}

float EnvironmentDistribution::texelDensity(int x, int y) const {
  const double* cdf = column_cdf_.data() + std::size_t(y) * (std::size_t(map_.width) + 1);
  const double weight = cdf[x + 1] - cdf[x];
  return float(weight * double(map_.width) * double(map_.height) / total_);
}

EnvironmentSample EnvironmentDistribution::sample(glm::vec2 u) const {
  EnvironmentSample out;
  if (black()) return out;
  const int w = map_.width, h = map_.height;
  // The row by the marginal, then the column by that row's conditional; the remainders place
  // the point uniformly inside the texel.
  const double row_target = double(u.x) * total_;
  const int y = findInterval(row_cdf_, row_target);
  const double row_weight = row_cdf_[std::size_t(y) + 1] - row_cdf_[std::size_t(y)];
  const double fy = std::clamp((row_target - row_cdf_[std::size_t(y)]) / row_weight, 0.0, 1.0);
  const double* cdf = column_cdf_.data() + std::size_t(y) * (std::size_t(w) + 1);
  const double column_target = double(u.y) * cdf[w];
  const int x = findInterval({cdf, std::size_t(w) + 1}, column_target);
  const double fx = std::clamp((column_target - cdf[x]) / (cdf[x + 1] - cdf[x]), 0.0, 1.0);

  const glm::vec2 uv{float((double(x) + fx) / double(w)), float((double(y) + fy) / double(h))};
  const double sin_theta = std::sin(kPi * double(uv.y));
  if (sin_theta <= 0) return out;
  out.direction = map_.toWorld(latLongDirection(uv));
  out.pdf = float(double(texelDensity(x, y)) / (2 * kPi * kPi * sin_theta));
  out.radiance = map_.intensity * map_.texel(x, y);
  return out;
}

float EnvironmentDistribution::pdf(const glm::vec3& world_direction) const {
  if (black()) return 0.0f;
  const glm::vec3 d = map_.toMap(world_direction);
  const glm::vec2 uv = latLongCoordinates(d);
  const double sin_theta = std::sin(kPi * double(uv.y));
  if (sin_theta <= 0) return 0.0f;
  const int x = std::min(int(uv.x * float(map_.width)), map_.width - 1);
  const int y = std::min(int(uv.y * float(map_.height)), map_.height - 1);
  return float(double(texelDensity(x, y)) / (2 * kPi * kPi * sin_theta));
}

}  // namespace gib::scene
