// Pass timings for tests that need timed jobs without rendering: the record the pass profiler
// would have made from the given per-frame samples, summarised as the harness summarises it.
#pragma once

#include "metrics/pass_timing_summary.h"

#include <string>
#include <vector>

namespace gib::test {

struct SyntheticPass {
  std::string path;                // "frame", "frame/shadow map", "iteration/update"
  std::vector<double> samples_ms;  // one per measured frame, on the reported clock
  int calls = 1;                   // entries per frame
  int gpu_commands = -1;           // draws and dispatches per frame; negative: not counted
};

// The first pass is the root; every pass needs as many samples as it.
metrics::PassTimings syntheticTimings(const std::vector<SyntheticPass>& passes,
                                      const std::string& clock = "gpu", int warmup_frames = 2);

// A record of the root pass alone ("frame", or "iteration" for `root`).
metrics::PassTimings frameTimings(const std::vector<double>& samples_ms,
                                  const std::string& clock = "gpu",
                                  const std::string& root = "frame");

}  // namespace gib::test
