#include "reports/results.h"

#include <cmath>

#include <algorithm>

namespace gib::reports {

namespace {

// passes[0] of metrics::passTimingsJson is the whole frame.
const nlohmann::ordered_json* framePass(const nlohmann::ordered_json& timings) {
  if (!timings.is_object() || !timings.contains("passes")) return nullptr;
  const auto& passes = timings.at("passes");
  if (!passes.is_array() || passes.empty()) return nullptr;
  return &passes.front();
}

}  // namespace

std::optional<double> JobResult::frameMedianMs() const {
  const nlohmann::ordered_json* frame = framePass(timings);
  if (!frame || !frame->contains("median_ms") || !frame->at("median_ms").is_number())
    return std::nullopt;
  return frame->at("median_ms").get<double>();
}

std::vector<double> JobResult::frameSamplesMs() const {
  const nlohmann::ordered_json* frame = framePass(timings);
  if (!frame) return {};
  const std::string clock = timings.value("clock", std::string("gpu"));
  const std::string key = clock == "cpu" ? "cpu_ms" : "gpu_ms";
  if (!frame->contains(key) || !frame->at(key).is_array()) return {};
  return frame->at(key).get<std::vector<double>>();
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

bool higherIsBetter(const std::string& name) {
  return name == "psnr" || name.rfind("ssim", 0) == 0;
}

double metricBadness(const std::string& name, double value) {
  if (name == "energy_ratio") return std::abs(value - 1.0);
  return higherIsBetter(name) ? -value : value;
}

}  // namespace gib::reports
