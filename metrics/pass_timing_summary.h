// Per-pass timing summaries of a profiled run, in the shape of Nijasure et al.'s Table 1 (each
// step of the frame, its time and its share of the frame): the typed form the harness stores
// (results.json's `timings`, written and read by results/results_json.h) and a human table. The
// record is plain data from realtime/gl/pass_record.h (no GL).
#pragma once

#include "metrics/timing_statistics.h"
#include "realtime/gl/pass_record.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gib::metrics {

// One pass over the measured frames.
struct PassTiming {
  std::string name, path;
  int depth = 0;
  TimingSummary reported;  // of the reported clock, ms per frame
  // Each clock's median where the record has its samples.
  std::optional<double> gpu_median_ms, cpu_median_ms;
  // Of the frame: the sum over frames of this pass's time over the sum of the frame's time, on
  // the reported clock (a ratio of totals, not a median of ratios, so shares of siblings add up).
  double share = 0;
  double calls_per_frame = 0;  // mean entries per measured frame
  // Mean draws and compute dispatches per measured frame, inner passes' included; nullopt for a
  // record made before they were counted.
  std::optional<double> gpu_commands_per_frame;
  // Per measured frame, so that a later run can be compared with a rank test; empty for a clock
  // the record does not have.
  std::vector<double> gpu_ms, cpu_ms;
  bool operator==(const PassTiming&) const = default;
};

// A profile summarised per pass.
struct PassTimings {
  std::string clock = "gpu";  // the reported clock: "gpu" (timestamp queries) or "cpu"
  bool precise = false;       // CPU time around a glFinish at each pass boundary
  int warmup_frames = 0;
  int measured_frames = 0;
  std::vector<PassTiming> passes;  // depth first, the root ("frame" or "iteration") first
  bool operator==(const PassTimings&) const = default;

  // The whole frame (or iteration); passes is never empty in a summary.
  const PassTiming& root() const { return passes.front(); }
  // The per-frame samples of the reported clock.
  const std::vector<double>& reportedSamples(const PassTiming& pass) const {
    return clock == "cpu" ? pass.cpu_ms : pass.gpu_ms;
  }
  // The pass with this path or name; nullptr when there is none.
  const PassTiming* find(std::string_view path_or_name) const;
  // The rate of the median frame; nullopt for a median of zero.
  std::optional<double> frameRateFps() const;
  // "GPU timestamp queries" or "CPU wall clock around glFinish (precise mode)".
  std::string clockDescription() const;
};

// One row per pass, depth first (a pass right after its parent, siblings in first-seen order),
// the frame first. Throws std::invalid_argument when there are no measured frames, when the
// reported clock is neither "gpu" nor "cpu" or has no samples, or when a pass's series do not
// have one value per measured frame.
PassTimings summarizeProfile(const rt::ProfileRecord& record);

// A table for people: pass names indented by depth, median, quartiles, minimum and maximum in
// ms, share of the frame, calls and GPU commands (draws, dispatches) per frame, and the other
// clock's median where the record has both; a header naming the reported clock and the frame
// counts, and a footer with the frame rate of the median frame and the share of the frame outside
// every pass.
std::string formatPassTable(const PassTimings& timings);

}  // namespace gib::metrics
