#include "reports/quantity.h"

#include "reports/number_format.h"
#include "reports/pass_timings_view.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <string_view>
#include <vector>

namespace gib::reports {

namespace {

constexpr std::string_view kFull = "full:";
constexpr std::string_view kStatistic = "statistic:";
constexpr std::string_view kParameter = "parameter:";
constexpr std::string_view kIteration = "iteration";

bool startsWith(std::string_view text, std::string_view prefix) {
  return text.substr(0, prefix.size()) == prefix;
}

std::optional<double> findValue(const NamedValues& values, std::string_view name) {
  for (const auto& [key, value] : values)
    if (key == name) return value;
  return std::nullopt;
}

std::optional<std::string> parameterText(const JobResult& job, std::string_view name) {
  for (const auto& [key, value] : job.parameters)
    if (key == name) return value;
  return std::nullopt;
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

std::optional<double> singleQuantityValue(const JobResult& job, const std::string& quantity);

}  // namespace

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

namespace {

std::optional<double> singleQuantityValue(const JobResult& job, const std::string& quantity) {
  const std::string_view q = quantity;
  if (startsWith(q, kFull)) return findValue(job.metrics_full, q.substr(kFull.size()));
  if (startsWith(q, kStatistic)) return findValue(job.statistics, q.substr(kStatistic.size()));
  if (startsWith(q, kParameter)) {
    const std::optional<std::string> text = parameterText(job, q.substr(kParameter.size()));
    return text ? parseNumber(*text) : std::nullopt;
  }
  if (q == "iterations")
    return job.iterations > 0 ? std::optional<double>(job.iterations) : std::nullopt;
  if (isIterationTiming(q)) {
    const std::optional<TimingsView> view = readTimings(job.iteration_timings);
    return view ? passMedianMs(*view, quantity) : std::nullopt;
  }
  if (const std::optional<double> metric = job.metric(quantity)) return metric;
  // A bare metric name measured only against the full reference (a reference job's own).
  if (const std::optional<double> full = findValue(job.metrics_full, q)) return full;
  const std::optional<TimingsView> view = readTimings(job.timings);
  return view ? passMedianMs(*view, quantity) : std::nullopt;
}

}  // namespace

std::optional<std::string> quantityText(const JobResult& job, const std::string& quantity) {
  const std::string_view q = quantity;
  if (q == "scene") return job.scene;
  if (startsWith(q, kParameter)) return parameterText(job, q.substr(kParameter.size()));
  const std::optional<double> value = quantityValue(job, quantity);
  if (!value) return std::nullopt;
  return formatNumber(*value);
}

std::string quantityLabel(const std::string& quantity) {
  const std::string_view q = quantity;
  if (startsWith(q, kFull))
    return fmt::format("{} against the full reference", q.substr(kFull.size()));
  if (startsWith(q, kStatistic)) return std::string(q.substr(kStatistic.size()));
  if (startsWith(q, kParameter)) return std::string(q.substr(kParameter.size()));
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
  for (std::string_view prefix : {kFull, kStatistic, kParameter})
    if (startsWith(q, prefix) && q.size() == prefix.size())
      return fmt::format("names no {} after '{}'",
                         prefix == kParameter   ? "parameter"
                         : prefix == kStatistic ? "statistic"
                                                : "metric",
                         prefix);
  if (q.back() == '/' || q.front() == '/') return "has an empty pass name";
  const std::size_t colon = q.find(':');
  if (colon != std::string_view::npos && !startsWith(q, kFull) && !startsWith(q, kStatistic) &&
      !startsWith(q, kParameter))
    return fmt::format("has an unknown prefix '{}:' (known: full:, statistic:, parameter:)",
                       q.substr(0, colon));
  return std::nullopt;
}

}  // namespace gib::reports
