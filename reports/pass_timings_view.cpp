#include "reports/pass_timings_view.h"

#include <cmath>
#include <limits>

namespace gib::reports {

namespace {

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

double numberOr(const nlohmann::ordered_json& object, const char* key, double fallback) {
  const auto it = object.find(key);
  return it != object.end() && it->is_number() ? it->get<double>() : fallback;
}

std::string textOr(const nlohmann::ordered_json& object, const char* key) {
  const auto it = object.find(key);
  return it != object.end() && it->is_string() ? it->get<std::string>() : std::string();
}

}  // namespace

std::optional<TimingsView> readTimings(const nlohmann::ordered_json& timings) {
  if (!timings.is_object()) return std::nullopt;
  const auto passes = timings.find("passes");
  if (passes == timings.end() || !passes->is_array() || passes->empty()) return std::nullopt;
  TimingsView view;
  view.clock = textOr(timings, "clock");
  view.clock_description = textOr(timings, "clock_description");
  view.warmup_frames = int(numberOr(timings, "warmup_frames", 0));
  view.measured_frames = int(numberOr(timings, "measured_frames", 0));
  const double fps = numberOr(timings, "frame_rate_fps", kMissing);
  if (!std::isnan(fps)) view.frame_rate_fps = fps;
  for (const auto& pass : *passes) {
    if (!pass.is_object()) continue;
    PassTimes row;
    row.name = textOr(pass, "name");
    row.path = textOr(pass, "path");
    row.depth = int(numberOr(pass, "depth", 0));
    row.median_ms = numberOr(pass, "median_ms", kMissing);
    row.first_quartile_ms = numberOr(pass, "first_quartile_ms", kMissing);
    row.third_quartile_ms = numberOr(pass, "third_quartile_ms", kMissing);
    row.share = numberOr(pass, "share", kMissing);
    row.calls_per_frame = numberOr(pass, "calls_per_frame", kMissing);
    view.passes.push_back(std::move(row));
  }
  if (view.passes.empty()) return std::nullopt;
  return view;
}

std::vector<PassBar> passBars(const TimingsView& view) {
  return {view.passes.begin(), view.passes.end()};
}

std::optional<double> passMedianMs(const TimingsView& view, const std::string& quantity) {
  if (quantity == "frame") return view.passes.front().median_ms;
  for (const PassTimes& pass : view.passes)
    if (pass.name == quantity || pass.path == quantity) return pass.median_ms;
  return std::nullopt;
}

}  // namespace gib::reports
