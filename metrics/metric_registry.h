// One place turns metric names into measurements: `gibench compare --metrics`, `gibench list
// metrics` and (later) the harness read this table.
#pragma once

#include "image/image.h"
#include "metrics/flip.h"
#include "metrics/image_metrics.h"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gib::metrics {

struct MetricOptions {
  double relative_epsilon = kRelativeEpsilon;  // ε of relMSE, MAPE, SMAPE
  bool reject_outliers = false;                // relMSE without the top 0.1% of pixels
  FlipViewingConditions flip;
};

struct MetricInfo {
  std::string name;
  std::string description;
};

// Every metric, in report order.
const std::vector<MetricInfo>& metricCatalogue();

// "all" or a comma-separated list of names; throws gib::InputError naming an unknown metric and
// listing the known ones.
std::vector<std::string> parseMetricList(std::string_view list);

struct MetricReport {
  // Named figures in report order: "mse", "relmse", "flip_mean", "flip_median", …
  std::vector<std::pair<std::string, double>> values;
  // Per-pixel maps (one channel) by metric name.
  std::vector<std::pair<std::string, image::Image>> maps;
  // Pixels with a NaN or infinite channel in the test image: their own figure, left out of
  // every other one.
  std::size_t nonfinite_pixels = 0;

  double value(std::string_view name) const;  // throws std::out_of_range if absent
};

// Throws std::invalid_argument unless both are RGB images of one size.
MetricReport evaluateMetrics(const image::Image& reference, const image::Image& test,
                             const std::vector<std::string>& names,
                             const MetricOptions& options = {});

}  // namespace gib::metrics
