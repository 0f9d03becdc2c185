#include "suites/primary_metric.h"

namespace gib::suites {

namespace {

constexpr const char* kPreferred = "relmse";

}  // namespace

std::string primaryMetric(const results::NamedValues& values) {
  for (const auto& [name, value] : values)
    if (name == kPreferred) return name;
  return values.empty() ? std::string() : values.front().first;
}

std::string primaryMetric(const std::vector<results::JobResult>& jobs) {
  std::string first;
  for (const results::JobResult& job : jobs) {
    const std::string metric = primaryMetric(job.metrics);
    if (metric == kPreferred) return metric;
    if (first.empty()) first = metric;
  }
  return first;
}

}  // namespace gib::suites
