// The per-pass timings of a job as the report shows them, read from JobResult::timings (the JSON
// of metrics::passTimingsJson). Reading is lenient: results.json keeps timings as opaque JSON, so
// a missing or mistyped number becomes NaN (shown as such, left out of charts) rather than an
// error that would stop the whole report.
#pragma once

#include "reports/svg_charts.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gib::reports {

struct PassTimes : PassBar {
  std::string path;  // "frame/shadow_maps"
  double share = 0;  // of the frame, on the reported clock
  double calls_per_frame = 0;
};

struct TimingsView {
  std::string clock;              // "gpu" or "cpu"
  std::string clock_description;  // "GPU timestamp queries", …
  int warmup_frames = 0, measured_frames = 0;
  std::optional<double> frame_rate_fps;
  std::vector<PassTimes> passes;  // depth first, the frame first
};

// nullopt when the job was not timed (null timings, as for reference jobs, or no passes).
std::optional<TimingsView> readTimings(const nlohmann::ordered_json& timings);

std::vector<PassBar> passBars(const TimingsView& view);

// The median of the pass named `quantity` (by name or path; "frame" is the whole frame), for
// the paper's timing rows. nullopt when there is no such pass.
std::optional<double> passMedianMs(const TimingsView& view, const std::string& quantity);

}  // namespace gib::reports
