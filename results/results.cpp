#include "results/results.h"

#include <algorithm>

namespace gib::results {

std::optional<double> JobResult::frameMedianMs() const {
  if (!timings || timings->passes.empty()) return std::nullopt;
  return timings->root().reported.median;
}

std::vector<double> JobResult::frameSamplesMs() const {
  if (!timings || timings->passes.empty()) return {};
  return timings->reportedSamples(timings->root());
}

std::optional<double> JobResult::metric(const std::string& name) const {
  for (const auto& [key, value] : metrics)
    if (key == name) return value;
  return std::nullopt;
}

const JobResult* RunResults::findJob(const std::string& id) const {
  auto it = std::find_if(jobs.begin(), jobs.end(), [&](const JobResult& j) { return j.id == id; });
  return it == jobs.end() ? nullptr : &*it;
}

}  // namespace gib::results
