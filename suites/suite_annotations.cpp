#include "suites/suite_annotations.h"

#include "common/join.h"
#include "metrics/metric_registry.h"
#include "realtime/technique.h"
#include "results/quantity.h"

#include <fmt/format.h>

#include <fnmatch.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace gib::suites {

namespace {

constexpr const char* kQuantityFix =
    "name a metric value (relmse, full:relmse), frame or a pass, iteration or "
    "iteration/<pass>, statistic:<name> or parameter:<name>";

// Every pass and every statistic `quantity` names must be declared by each technique in
// `techniques`; a pass named for jobs that have no technique (reference jobs are not timed) is an
// error too. Passes and statistics are an interface of each technique (`gibench list
// techniques` lists them): a renamed one must fail here, not leave a figure without its numbers.
// `what` names the quantity's key in messages ("chart.y").
void checkDeclaredByTechniques(const TomlErrorReporter& errors, const toml::node& node,
                               std::string_view what, const std::string& quantity,
                               const std::set<std::string>& techniques,
                               std::string_view jobs_description) {
  for (const std::string& pass : results::quantityPasses(quantity)) {
    if (techniques.empty())
      errors.fail(node,
                  fmt::format("{} '{}' names the pass '{}', but {} no technique: reference "
                              "jobs are not timed",
                              what, quantity, pass, jobs_description),
                  "name a metric value, or give jobs of a real-time technique");
    for (const std::string& technique : techniques) {
      const rt::TechniqueInfo& info = rt::findTechnique(technique);
      if (info.passes.declares(pass)) continue;
      errors.fail(node,
                  fmt::format("{} '{}' names the pass '{}', which technique '{}' does not declare",
                              what, quantity, pass, technique),
                  fmt::format("name one of its passes: {} (`gibench list techniques`)",
                              joinNames(info.passes.passes(), ", ",
                                        [](const rt::DeclaredPass& p) { return p.path; })));
    }
  }
  for (const std::string& statistic : results::quantityStatistics(quantity))
    for (const std::string& technique : techniques) {
      const rt::TechniqueInfo& info = rt::findTechnique(technique);
      if (rt::findDeclaredOutput(info.statistics, statistic)) continue;
      errors.fail(node,
                  fmt::format("{} '{}' names the statistic '{}', which technique '{}' does not "
                              "declare",
                              what, quantity, statistic, technique),
                  info.statistics.empty()
                      ? std::string("it reports no statistics (`gibench list techniques`)")
                      : fmt::format("name one of its statistics: {} (`gibench list techniques`)",
                                    joinNames(info.statistics, ", ",
                                              [](const rt::DeclaredOutput& s) { return s.name; })));
    }
}

// The techniques of the jobs (reference jobs have none).
std::set<std::string> techniquesOf(const std::vector<const Job*>& jobs) {
  std::set<std::string> techniques;
  for (const Job* job : jobs)
    if (job->technique != kReferenceTechnique) techniques.insert(job->technique);
  return techniques;
}

double nonNegative(const TomlTableReader& t, const toml::node& node, std::string_view key,
                   double max) {
  const double value = t.number(node, key);
  if (value < 0 || value > max)
    t.errors().fail(node, fmt::format("{} must be in [0, {}]", t.path(key), max),
                    fmt::format("write e.g. {} = 0.05", key));
  return value;
}

results::Tolerance readMetricTolerance(const TomlTableReader& parent, const std::string& key,
                                       const toml::node& node) {
  const std::string name = parent.path(key);
  const TomlTableReader t(
      parent.errors(),
      requireTomlTable(parent.errors(), node, name,
                       fmt::format("write {} = {{ absolute = 0.0, relative = 0.05 }}", key)),
      name, name, {"absolute", "relative"});
  results::Tolerance tolerance;
  if (const toml::node* n = t.find("absolute"))
    tolerance.absolute = nonNegative(t, *n, "absolute", 1e30);
  if (const toml::node* n = t.find("relative"))
    tolerance.relative = nonNegative(t, *n, "relative", 1e6);
  return tolerance;
}

results::TimingTolerance readTimingTolerance(const TomlTableReader& parent,
                                             const toml::node& node) {
  const std::string name = parent.path("frame_time");
  const TomlTableReader t(
      parent.errors(),
      requireTomlTable(parent.errors(), node, name,
                       "write frame_time = { relative = 0.1, significance = 0.01 }"),
      name, name, {"relative", "significance"});
  results::TimingTolerance tolerance;
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

// A paper value's relative tolerance: a finite number, not negative. The message names the entry
// by its job and quantity too: a figure suite has dozens of [[paper]] entries.
double readPaperTolerance(const TomlTableReader& t, const toml::node& node,
                          const results::PaperValue& v) {
  const double tolerance = tomlNumber(node);  // NaN for a string, an array, …
  if (!(std::isfinite(tolerance) && tolerance >= 0))
    t.errors().fail(
        node,
        fmt::format("{} (job '{}', quantity '{}') has tolerance = {}, but a tolerance must be a "
                    "finite number ≥ 0",
                    t.header(), v.job, v.quantity,
                    node.is_number() ? fmt::format("{}", tolerance) : "a non-number"),
        "write the allowed relative difference from the paper's value, e.g. tolerance = 0.05 "
        "for ±5%, or leave it out to show the value without a verdict");
  return tolerance;
}

}  // namespace

results::Tolerances readTolerances(const TomlTableReader& root, const toml::node& node) {
  const toml::table& table = requireTomlTable(
      root.errors(), node, "tolerances", "write [tolerances] with relmse = { relative = 0.05 }");
  // Keys are checked below, one by one, with a message of their own.
  std::vector<std::string> keys;
  for (const auto& [key, value] : table) keys.emplace_back(key.str());
  const TomlTableReader t(root.errors(), table, "tolerances", "[tolerances]", keys);
  results::Tolerances tolerances;
  for (const auto& [key_node, value] : entriesInFileOrder(table)) {
    const std::string key(key_node->str());
    if (key == "frame_time") {
      tolerances.timing = readTimingTolerance(t, *value);
      continue;
    }
    if (key != "default" && !metrics::findMetricValue(key))
      root.errors().fail(key_node->source(), fmt::format("[tolerances] has no metric '{}'", key),
                         "use default, frame_time or a metric value name such as relmse or "
                         "flip_mean (`gibench list metrics`)");
    const results::Tolerance tolerance = readMetricTolerance(t, key, *value);
    if (key == "default")
      tolerances.metric_default = tolerance;
    else
      tolerances.metrics[key] = tolerance;
  }
  return tolerances;
}

std::vector<results::PaperValue> readPaperValues(const TomlTableReader& root,
                                                 const std::vector<Job>& jobs) {
  std::vector<results::PaperValue> values;
  const std::vector<const toml::table*> entries = tomlTableArray(root, "paper");
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const TomlTableReader t(root.errors(), *entries[i], "paper",
                            fmt::format("[[paper]] entry {}", i + 1),
                            {"job", "quantity", "value", "unit", "source", "note", "tolerance"});
    results::PaperValue v;
    const toml::node& job = t.require("job", "\"cornell-direct/shadow=pcf\"");
    v.job = t.string(job, "job");
    const auto found =
        std::find_if(jobs.begin(), jobs.end(), [&](const Job& j) { return j.id == v.job; });
    if (found == jobs.end())
      t.errors().fail(job, fmt::format("paper.job '{}' is not a job of this suite", v.job),
                      "use a job id as `gibench run --list` prints it");
    const toml::node& quantity = t.require("quantity", "\"relmse\"");
    v.quantity = t.string(quantity, "quantity");
    if (const std::optional<std::string> error = results::quantitySyntaxError(v.quantity))
      t.errors().fail(quantity, fmt::format("{} '{}' {}", t.path("quantity"), v.quantity, *error),
                      kQuantityFix);
    checkDeclaredByTechniques(t.errors(), quantity, t.path("quantity"), v.quantity,
                              techniquesOf({&*found}), fmt::format("job '{}' has", v.job));
    v.value = t.number(t.require("value", "12.5"), "value");
    v.source = t.string(t.require("source", "\"Nijasure et al. 2005, Table 1\""), "source");
    if (const toml::node* n = t.find("unit")) v.unit = t.string(*n, "unit");
    if (const toml::node* n = t.find("note")) v.note = t.string(*n, "note");
    if (const toml::node* n = t.find("tolerance")) v.tolerance = readPaperTolerance(t, *n, v);
    values.push_back(std::move(v));
  }
  return values;
}

std::vector<results::ChartSpec> readCharts(const TomlTableReader& root,
                                           const std::vector<Job>& jobs) {
  std::vector<results::ChartSpec> charts;
  const std::vector<const toml::table*> entries = tomlTableArray(root, "chart");
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const TomlTableReader t(root.errors(), *entries[i], "chart",
                            fmt::format("[[chart]] entry {}", i + 1),
                            {"title", "jobs", "x", "y", "series", "log_x", "log_y", "front"});
    results::ChartSpec c;
    c.title = t.string(t.require("title", "\"Fig. 7: time per iteration\""), "title");
    if (const toml::node* n = t.find("jobs")) {
      c.jobs = t.string(*n, "jobs");
      if (std::none_of(jobs.begin(), jobs.end(),
                       [&](const Job& j) { return fnmatch(c.jobs.c_str(), j.id.c_str(), 0) == 0; }))
        t.errors().fail(*n, fmt::format("chart.jobs '{}' matches no job of this suite", c.jobs),
                        "use a glob over job ids as `gibench run --list` prints them");
    }
    std::vector<const Job*> matched;
    for (const Job& j : jobs)
      if (fnmatch(c.jobs.c_str(), j.id.c_str(), 0) == 0) matched.push_back(&j);
    const std::set<std::string> techniques = techniquesOf(matched);
    auto quantity = [&](std::string_view key, std::string_view example) {
      const toml::node& node = t.require(key, example);
      std::string value = t.string(node, key);
      if (const std::optional<std::string> error = results::quantitySyntaxError(value))
        t.errors().fail(node, fmt::format("{} '{}' {}", t.path(key), value, *error), kQuantityFix);
      checkDeclaredByTechniques(t.errors(), node, t.path(key), value, techniques,
                                fmt::format("the jobs '{}' have", c.jobs));
      return value;
    };
    c.x = quantity("x", "\"statistic:vertices\"");
    c.y = quantity("y", "\"iteration\"");
    if (t.find("series")) c.series = quantity("series", "\"parameter:selection\"");
    if (const toml::node* n = t.find("log_x")) c.log_x = t.boolean(*n, "log_x");
    if (const toml::node* n = t.find("log_y")) c.log_y = t.boolean(*n, "log_y");
    if (const toml::node* n = t.find("front")) c.front = t.boolean(*n, "front");
    charts.push_back(std::move(c));
  }
  return charts;
}

void checkQuantity(const TomlErrorReporter& errors, const toml::node& node, std::string_view what,
                   const std::string& quantity, const Job& job) {
  if (const std::optional<std::string> error = results::quantitySyntaxError(quantity))
    errors.fail(node, fmt::format("{} '{}' {}", what, quantity, *error), kQuantityFix);
  checkDeclaredByTechniques(errors, node, what, quantity, techniquesOf({&job}),
                            fmt::format("job '{}' has", job.id));
}

}  // namespace gib::suites
