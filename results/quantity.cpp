#include "results/quantity.h"

#include "metrics/metric_registry.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <string_view>
#include <vector>

namespace gib::results {

namespace {

constexpr std::string_view kFull = "full:";
constexpr std::string_view kStatistic = "statistic:";
constexpr std::string_view kIteration = "iteration";

bool startsWith(std::string_view text, std::string_view prefix) {
  return text.substr(0, prefix.size()) == prefix;
}

std::optional<double> parseNumber(const std::string& text) {
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

bool isIterationTiming(std::string_view quantity) {
  return quantity == kIteration ||
         (startsWith(quantity, kIteration) && quantity.size() > kIteration.size() &&
          quantity[kIteration.size()] == '/');
}

// A metric value name, as the registry declares it ("relmse", "flip_mean").
bool isMetricValue(std::string_view name) {
  return metrics::findMetricValue(name) != nullptr;
}

// Whether a single term names a pass: anything that is not a prefixed name, a metric value, the
// iteration count or the scene.
bool isPassTerm(std::string_view term) {
  return !startsWith(term, kFull) && !startsWith(term, kStatistic) &&
         !startsWith(term, kParameterPrefix) && term != "iterations" && term != "scene" &&
         !isMetricValue(term);
}

// "a + b + c": the terms, trimmed.
std::vector<std::string> sumTerms(std::string_view quantity) {
  std::vector<std::string> terms;
  std::size_t start = 0;
  while (start <= quantity.size()) {
    const std::size_t end = std::min(quantity.find('+', start), quantity.size());
    std::string_view term = quantity.substr(start, end - start);
    while (!term.empty() && term.front() == ' ') term.remove_prefix(1);
    while (!term.empty() && term.back() == ' ') term.remove_suffix(1);
    terms.emplace_back(term);
    start = end + 1;
  }
  return terms;
}

std::optional<double> passMedianMs(const std::optional<metrics::PassTimings>& timings,
                                   std::string_view pass) {
  if (!timings) return std::nullopt;
  const metrics::PassTiming* found = timings->find(pass);
  return found ? std::optional<double>(found->reported.median) : std::nullopt;
}

std::optional<double> singleQuantityValue(const JobResult& job, const std::string& quantity) {
  const std::string_view q = quantity;
  if (startsWith(q, kFull)) return findValue(job.metrics_full, q.substr(kFull.size()));
  if (startsWith(q, kStatistic)) return findValue(job.statistics, q.substr(kStatistic.size()));
  if (startsWith(q, kParameterPrefix)) {
    const std::optional<std::string> text = parameterText(job, q.substr(kParameterPrefix.size()));
    return text ? parseNumber(*text) : std::nullopt;
  }
  if (q == "iterations")
    return job.iterations > 0 ? std::optional<double>(job.iterations) : std::nullopt;
  if (q == "scene") return std::nullopt;
  if (isMetricValue(q)) {
    if (const std::optional<double> metric = job.metric(quantity)) return metric;
    // A metric measured only against the full reference (a reference job's own).
    return findValue(job.metrics_full, q);
  }
  return passMedianMs(isIterationTiming(q) ? job.iteration_timings : job.timings, q);
}

}  // namespace

std::optional<std::string> parameterText(const JobResult& job, std::string_view name) {
  // "scene.<name>": a scene parameter, as job ids write them ("scene.particles=512").
  constexpr std::string_view kScene = "scene.";
  const bool scene = name.starts_with(kScene);
  if (scene) name.remove_prefix(kScene.size());
  for (const auto& [key, value] : scene ? job.scene_parameters : job.parameters)
    if (key == name) return value;
  return std::nullopt;
}

std::optional<double> quantityValue(const JobResult& job, const std::string& quantity) {
  if (quantity.find('+') == std::string::npos) return singleQuantityValue(job, quantity);
  double sum = 0;
  for (const std::string& term : sumTerms(quantity)) {
    const std::optional<double> value = singleQuantityValue(job, term);
    if (!value) return std::nullopt;
    sum += *value;
  }
  return sum;
}

std::string quantityLabel(const std::string& quantity) {
  const std::string_view q = quantity;
  if (startsWith(q, kFull))
    return fmt::format("{} against the full reference", q.substr(kFull.size()));
  if (startsWith(q, kStatistic)) return std::string(q.substr(kStatistic.size()));
  if (startsWith(q, kParameterPrefix)) return std::string(q.substr(kParameterPrefix.size()));
  if (q == "iterations") return "iterations";
  if (q == kIteration) return "ms per iteration";
  if (isIterationTiming(q))
    return fmt::format("ms per iteration ({})", q.substr(kIteration.size() + 1));
  if (q == "frame") return "ms per frame";
  return quantity;
}

std::optional<std::string> quantitySyntaxError(const std::string& quantity) {
  if (quantity.find('+') != std::string::npos) {
    for (const std::string& term : sumTerms(quantity))
      if (std::optional<std::string> error = quantitySyntaxError(term))
        return fmt::format("has a term that {}", *error);
    return std::nullopt;
  }
  const std::string_view q = quantity;
  if (q.empty()) return "is empty";
  for (std::string_view prefix : {kFull, kStatistic, kParameterPrefix})
    if (startsWith(q, prefix) && q.size() == prefix.size())
      return fmt::format("names no {} after '{}'",
                         prefix == kParameterPrefix ? "parameter"
                         : prefix == kStatistic     ? "statistic"
                                                    : "metric",
                         prefix);
  if (q.back() == '/' || q.front() == '/') return "has an empty pass name";
  const std::size_t colon = q.find(':');
  if (colon != std::string_view::npos && !startsWith(q, kFull) && !startsWith(q, kStatistic) &&
      !startsWith(q, kParameterPrefix))
    return fmt::format("has an unknown prefix '{}:' (known: full:, statistic:, parameter:)",
                       q.substr(0, colon));
  return std::nullopt;
}

std::vector<std::string> quantityPasses(const std::string& quantity) {
  std::vector<std::string> passes;
  for (const std::string& term : sumTerms(quantity))
    if (isPassTerm(term)) passes.push_back(term);
  return passes;
}

std::vector<std::string> quantityStatistics(const std::string& quantity) {
  std::vector<std::string> statistics;
  for (const std::string& term : sumTerms(quantity))
    if (startsWith(term, kStatistic)) statistics.push_back(term.substr(kStatistic.size()));
  return statistics;
}

}  // namespace gib::results
