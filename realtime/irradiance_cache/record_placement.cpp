#include "realtime/irradiance_cache/record_placement.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace gib::rt {

glm::ivec4 zonePixelRect(const CameraTransform& camera, int width, int height,
                         const gpu::IrradianceRecord& record, float accuracy) {
  const glm::vec4 ndc =
      gpu::sphereScreenRect(camera.view, camera.projection, glm::vec3(record.position_radius),
                            accuracy * record.position_radius.w);
  // Pixel i's centre is at NDC (i + 0.5)·2/width − 1.
  auto first = [](float ndc_value, int size) {
    return std::max(0, int(std::ceil((ndc_value + 1.0f) * 0.5f * float(size) - 0.5f)));
  };
  auto last = [](float ndc_value, int size) {
    return std::min(size - 1, int(std::floor((ndc_value + 1.0f) * 0.5f * float(size) - 0.5f)));
  };
  return {first(ndc.x, width), first(ndc.y, height), last(ndc.z, width), last(ndc.w, height)};
}

RecordPlacement::RecordPlacement(const SurfaceImage& surfaces, const CameraTransform& camera,
                                 const RecordPlacementSettings& settings)
    : surfaces_(surfaces),
      camera_(camera),
      settings_(settings),
      pixel_angle_(2.0f / (camera.projection[1][1] * float(surfaces.height))),
      weights_(std::size_t(surfaces.width) * std::size_t(surfaces.height), 0.0f),
      spacing_(std::max(1, settings.coarsest_spacing)) {}

std::vector<glm::ivec2> RecordPlacement::nextRound() {
  const int width = surfaces_.width, height = surfaces_.height;
  if (settings_.scanline) {
    for (; cursor_ < weights_.size(); ++cursor_)
      if (surfaces_.valid[cursor_] && weights_[cursor_] == 0) {
        ++rounds_;
        return {{int(cursor_ % std::size_t(width)), int(cursor_ / std::size_t(width))}};
      }
    return {};
  }
  const int claim = std::max(0, int(std::ceil(settings_.min_zone_pixels)) - 1);
  for (;;) {
    const int s = spacing_;
    std::vector<glm::ivec2> round;
    std::vector<std::uint8_t> claimed;  // pixels near a record of this round
    if (claim > 0 && s <= claim) claimed.assign(weights_.size(), 0);
    for (int y = s / 2; y < height; y += s)
      for (int x = s / 2; x < width; x += s) {
        const std::size_t i = surfaces_.index(x, y);
        if (!surfaces_.valid[i] || weights_[i] > 0 || (!claimed.empty() && claimed[i])) continue;
        round.push_back({x, y});
        if (claimed.empty()) continue;
        for (int v = std::max(0, y - claim); v <= std::min(height - 1, y + claim); ++v)
          for (int u = std::max(0, x - claim); u <= std::min(width - 1, x + claim); ++u)
            claimed[surfaces_.index(u, v)] = 1;
      }
    spacing_ = std::max(1, s / 2);
    if (!round.empty()) {
      ++rounds_;
      return round;
    }
    if (s == 1) return round;
  }
}

void RecordPlacement::add(std::span<gpu::IrradianceRecord> records) {
  const float a = settings_.accuracy;
  for (gpu::IrradianceRecord& record : records) {
    const glm::vec3 p(record.position_radius);
    const float footprint = glm::length(p - camera_.position) * pixel_angle_;
    const float lo = settings_.min_zone_pixels * footprint / a;
    const float hi = settings_.max_zone_pixels * footprint / a;
    record.position_radius.w = std::clamp(record.position_radius.w, lo, hi);
    const glm::ivec4 rect = zonePixelRect(camera_, surfaces_.width, surfaces_.height, record, a);
    for (int y = rect.y; y <= rect.w; ++y)
      for (int x = rect.x; x <= rect.z; ++x) {
        const std::size_t i = surfaces_.index(x, y);
        if (!surfaces_.valid[i]) continue;
        const float w = gpu::recordWeight(record, surfaces_.position[i], surfaces_.normal[i]);
        if (w > 1.0f / a) weights_[i] += w;
      }
  }
}

}  // namespace gib::rt
