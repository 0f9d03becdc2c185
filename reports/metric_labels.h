// How the report names a metric value for people: its label, its definition, which way is better
// and the parameters it was computed with, all read from the metric registry
// (metrics/metric_registry.h), so that a value the registry gains is labelled and explained
// without a change here. results.json keeps the registry's names; these are display only.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace gib::reports {

// The value's label in the metric registry (FLIP's percentiles named as what they are: percentiles
// of FLIP's weighted histogram, "flip_median" → "flip weighted median"), else its name.
std::string metricLabel(std::string_view value);

// For a tooltip: the definition, the direction and the parameters, then the name in
// results.json: "relative MSE (x-r)^2/(r^2+eps) …; lower is better; ε = 0.01; results.json:
// relmse". A value no metric declares says so.
std::string metricDescription(std::string_view value);

// metricLabel (escaped) in a <span> whose title is metricDescription.
std::string metricLabelHtml(std::string_view value);

// A table of the given values, a row per metric that declares them (in first-seen order): the
// values' labels, the metric's definition, which way each is better, its parameters. Empty for
// no values.
std::string metricLegend(const std::vector<std::string>& values);

}  // namespace gib::reports
