#include "results/results.h"

#include "metrics/timing_statistics.h"

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

std::vector<double> JobResult::repeatMediansMs() const {
  std::vector<double> medians;
  for (const metrics::PassTimings& repeat : repeats)
    if (!repeat.passes.empty()) medians.push_back(repeat.root().reported.median);
  if (medians.empty())
    if (const std::optional<double> frame = frameMedianMs()) medians.push_back(*frame);
  return medians;
}

std::optional<double> JobResult::runMedianMs() const {
  const std::vector<double> medians = repeatMediansMs();
  if (medians.empty()) return std::nullopt;
  return metrics::quantile(medians, 0.5);
}

std::optional<double> findValue(const NamedValues& values, std::string_view name) {
  for (const auto& [key, value] : values)
    if (key == name) return value;
  return std::nullopt;
}

std::optional<double> JobResult::metric(const std::string& name) const {
  return findValue(metrics, name);
}

const JobResult* RunResults::findJob(const std::string& id) const {
  auto it = std::find_if(jobs.begin(), jobs.end(), [&](const JobResult& j) { return j.id == id; });
  return it == jobs.end() ? nullptr : &*it;
}

}  // namespace gib::results
