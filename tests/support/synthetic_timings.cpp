#include "support/synthetic_timings.h"

#include <algorithm>

namespace gib::test {

metrics::PassTimings syntheticTimings(const std::vector<SyntheticPass>& passes,
                                      const std::string& clock, int warmup_frames) {
  rt::ProfileRecord record;
  record.reported_clock = clock;
  record.precise = clock == "cpu";
  record.warmup_frames = warmup_frames;
  record.measured_frames = passes.empty() ? 0 : int(passes.front().samples_ms.size());
  for (const SyntheticPass& pass : passes) {
    rt::PassRecord r;
    r.path = pass.path;
    r.name = pass.path.substr(pass.path.rfind('/') + 1);
    r.depth = int(std::count(pass.path.begin(), pass.path.end(), '/'));
    (clock == "cpu" ? r.cpu_ms : r.gpu_ms) = pass.samples_ms;
    r.calls.assign(pass.samples_ms.size(), pass.calls);
    if (pass.gpu_commands >= 0) r.gpu_commands.assign(pass.samples_ms.size(), pass.gpu_commands);
    record.passes.push_back(std::move(r));
  }
  return metrics::summarizeProfile(record);
}

metrics::PassTimings frameTimings(const std::vector<double>& samples_ms, const std::string& clock,
                                  const std::string& root) {
  return syntheticTimings({{root, samples_ms}}, clock);
}

}  // namespace gib::test
