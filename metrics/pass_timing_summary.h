// Per-pass timing summaries of a profiled run, in the shape of Nijasure et al.'s Table 1 (each
// step of the frame, its time and its share of the frame), as a human table and as the JSON the
// harness stores. The record is plain data from realtime/gl/pass_record.h (no GL).
#pragma once

#include "metrics/timing_statistics.h"
#include "realtime/gl/pass_record.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gib::metrics {

struct PassTimingRow {
  std::string name, path;
  int depth = 0;
  TimingSummary reported;                 // of the record's reported clock, ms per frame
  std::optional<TimingSummary> gpu, cpu;  // each clock the record has samples of
  // Of the frame: the sum over frames of this pass's time over the sum of the frame's time, on
  // the reported clock (a ratio of totals, not a median of ratios, so shares of siblings add up).
  double share = 0;
  double calls_per_frame = 0;  // mean entries per measured frame
};

// One row per pass, depth first (a pass right after its parent, siblings in first-seen order),
// the frame first. Throws std::invalid_argument when there are no measured frames, when the
// reported clock is neither "gpu" nor "cpu" or has no samples, or when a pass's series do not
// have one value per measured frame.
std::vector<PassTimingRow> summarizeProfile(const rt::ProfileRecord& record);

// A table for people: pass names indented by depth, median, quartiles, minimum and maximum in
// ms, share of the frame, calls per frame, and the other clock's median where the record has
// both; a header naming the reported clock and the frame counts, and a footer with the frame rate
// of the median frame and the share of the frame outside every pass.
std::string formatPassTable(const rt::ProfileRecord& record,
                            const std::vector<PassTimingRow>& rows);

// The same for the harness, with each pass's per-frame samples of both clocks, so that a later
// run can be compared with a rank test.
nlohmann::ordered_json passTimingsJson(const rt::ProfileRecord& record,
                                       const std::vector<PassTimingRow>& rows);

}  // namespace gib::metrics
