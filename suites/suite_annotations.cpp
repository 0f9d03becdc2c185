#include "suites/suite_annotations.h"

#include "reports/quantity.h"

#include "metrics/metric_registry.h"

#include <fmt/format.h>

#include <fnmatch.h>

#include <algorithm>
#include <string>

namespace gib::suites {

namespace {

// A metric value name is a catalogue name ("relmse") or one with a suffix ("flip_mean").
bool isMetricValueName(const std::string& name) {
  return std::any_of(metrics::metricCatalogue().begin(), metrics::metricCatalogue().end(),
                     [&](const metrics::MetricInfo& info) {
                       return name == info.name || name.rfind(info.name + "_", 0) == 0;
                     });
}

double nonNegative(const TomlTableReader& t, const toml::node& node, std::string_view key,
                   double max) {
  const double value = t.number(node, key);
  if (value < 0 || value > max)
    t.errors().fail(node, fmt::format("{} must be in [0, {}]", t.path(key), max),
                    fmt::format("write e.g. {} = 0.05", key));
  return value;
}

reports::Tolerance readMetricTolerance(const TomlTableReader& parent, const std::string& key,
                                       const toml::node& node) {
  const std::string name = parent.path(key);
  const TomlTableReader t(
      parent.errors(),
      requireTomlTable(parent.errors(), node, name,
                       fmt::format("write {} = {{ absolute = 0.0, relative = 0.05 }}", key)),
      name, name, {"absolute", "relative"});
  reports::Tolerance tolerance;
  if (const toml::node* n = t.find("absolute"))
    tolerance.absolute = nonNegative(t, *n, "absolute", 1e30);
  if (const toml::node* n = t.find("relative"))
    tolerance.relative = nonNegative(t, *n, "relative", 1e6);
  return tolerance;
}

reports::TimingTolerance readTimingTolerance(const TomlTableReader& parent,
                                             const toml::node& node) {
  const std::string name = parent.path("frame_time");
  const TomlTableReader t(
      parent.errors(),
      requireTomlTable(parent.errors(), node, name,
                       "write frame_time = { relative = 0.1, significance = 0.01 }"),
      name, name, {"relative", "significance"});
  reports::TimingTolerance tolerance;
  if (const toml::node* n = t.find("relative"))
    tolerance.relative = nonNegative(t, *n, "relative", 1e6);
  if (const toml::node* n = t.find("significance")) {
    tolerance.significance = t.number(*n, "significance");
    if (!(tolerance.significance > 0 && tolerance.significance < 1))
      t.errors().fail(*n, fmt::format("{} must be in (0, 1)", t.path("significance")),
                      "write e.g. significance = 0.01");
  }
  return tolerance;
}

}  // namespace

reports::Tolerances readTolerances(const TomlTableReader& root, const toml::node& node) {
  const toml::table& table = requireTomlTable(
      root.errors(), node, "tolerances", "write [tolerances] with relmse = { relative = 0.05 }");
  // Keys are checked below, one by one, with a message of their own.
  std::vector<std::string> keys;
  for (const auto& [key, value] : table) keys.emplace_back(key.str());
  const TomlTableReader t(root.errors(), table, "tolerances", "[tolerances]", keys);
  reports::Tolerances tolerances;
  for (const auto& [key_node, value] : entriesInFileOrder(table)) {
    const std::string key(key_node->str());
    if (key == "frame_time") {
      tolerances.timing = readTimingTolerance(t, *value);
      continue;
    }
    if (key != "default" && !isMetricValueName(key))
      root.errors().fail(key_node->source(), fmt::format("[tolerances] has no metric '{}'", key),
                         "use default, frame_time or a metric value name such as relmse or "
                         "flip_mean (`gibench list metrics`)");
    const reports::Tolerance tolerance = readMetricTolerance(t, key, *value);
    if (key == "default")
      tolerances.metric_default = tolerance;
    else
      tolerances.metrics[key] = tolerance;
  }
  return tolerances;
}

std::vector<reports::PaperValue> readPaperValues(const TomlTableReader& root,
                                                 const std::vector<Job>& jobs) {
  std::vector<reports::PaperValue> values;
  const std::vector<const toml::table*> entries = tomlTableArray(root, "paper");
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const TomlTableReader t(root.errors(), *entries[i], "paper",
                            fmt::format("[[paper]] entry {}", i + 1),
                            {"job", "quantity", "value", "unit", "source", "note"});
    reports::PaperValue v;
    const toml::node& job = t.require("job", "\"cornell-direct/shadow=pcf\"");
    v.job = t.string(job, "job");
    if (std::none_of(jobs.begin(), jobs.end(), [&](const Job& j) { return j.id == v.job; }))
      t.errors().fail(job, fmt::format("paper.job '{}' is not a job of this suite", v.job),
                      "use a job id as `gibench run --list` prints it");
    v.quantity = t.string(t.require("quantity", "\"relmse\""), "quantity");
    v.value = t.number(t.require("value", "12.5"), "value");
    v.source = t.string(t.require("source", "\"Nijasure et al. 2005, Table 1\""), "source");
    if (const toml::node* n = t.find("unit")) v.unit = t.string(*n, "unit");
    if (const toml::node* n = t.find("note")) v.note = t.string(*n, "note");
    values.push_back(std::move(v));
  }
  return values;
}

std::vector<reports::ChartSpec> readCharts(const TomlTableReader& root,
                                           const std::vector<Job>& jobs) {
  std::vector<reports::ChartSpec> charts;
  const std::vector<const toml::table*> entries = tomlTableArray(root, "chart");
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const TomlTableReader t(root.errors(), *entries[i], "chart",
                            fmt::format("[[chart]] entry {}", i + 1),
                            {"title", "jobs", "x", "y", "series", "log_x", "log_y", "front"});
    reports::ChartSpec c;
    c.title = t.string(t.require("title", "\"Fig. 7: time per iteration\""), "title");
    auto quantity = [&](std::string_view key, std::string_view example) {
      const toml::node& node = t.require(key, example);
      std::string value = t.string(node, key);
      if (const std::optional<std::string> error = reports::quantitySyntaxError(value))
        t.errors().fail(node, fmt::format("{} '{}' {}", t.path(key), value, *error),
                        "name a metric value (relmse, full:relmse), frame or a pass, iteration "
                        "or iteration/<pass>, statistic:<name> or parameter:<name>");
      return value;
    };
    c.x = quantity("x", "\"statistic:vertices\"");
    c.y = quantity("y", "\"iteration\"");
    if (t.find("series")) c.series = quantity("series", "\"parameter:selection\"");
    if (const toml::node* n = t.find("jobs")) {
      c.jobs = t.string(*n, "jobs");
      if (std::none_of(jobs.begin(), jobs.end(),
                       [&](const Job& j) { return fnmatch(c.jobs.c_str(), j.id.c_str(), 0) == 0; }))
        t.errors().fail(*n, fmt::format("chart.jobs '{}' matches no job of this suite", c.jobs),
                        "use a glob over job ids as `gibench run --list` prints them");
    }
    if (const toml::node* n = t.find("log_x")) c.log_x = t.boolean(*n, "log_x");
    if (const toml::node* n = t.find("log_y")) c.log_y = t.boolean(*n, "log_y");
    if (const toml::node* n = t.find("front")) c.front = t.boolean(*n, "front");
    charts.push_back(std::move(c));
  }
  return charts;
}

}  // namespace gib::suites
