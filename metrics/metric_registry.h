// One place turns metric names into measurements: `gibench compare --metrics`, `gibench list
// metrics`, suites and the harness read this table. It also declares each value a metric reports
// ("flip" reports flip_mean, flip_median, …) and which way is better, which `gibench diff`, the
// report's colours and suite tolerances rely on.
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
  // Pixels whose primary hit the test image's renderer and the reference disagree on (one
  // channel, non-zero: disagree; reference/primary_agreement.h), or null when not checked. Every
  // value keeps them; relmse_agreeing is relMSE without them.
  const image::Image* disagreement = nullptr;
  // The pixels a technique names as what its own light reaches (one channel, non-zero: inside;
  // rt::Technique::measuredRegion: a gathered object, the mirrors and glass), or null. Every
  // value keeps all pixels; relmse_region is relMSE over these alone.
  const image::Image* region = nullptr;
};

// Which way a value improves.
enum class MetricDirection {
  kLowerIsBetter,   // errors: MSE, relMSE, FLIP
  kHigherIsBetter,  // similarities: PSNR, SSIM
  kTowardOne,       // ratios whose ideal is 1: energy_ratio
  // Describes an error rather than being one (how concentrated relMSE is): no direction, so a
  // change is never an improvement or a regression.
  kDescriptive,
};

struct MetricValueInfo {
  std::string name;  // "flip_mean"
  MetricDirection direction = MetricDirection::kLowerIsBetter;
  // For people (the report): a label where the name would mislead ("flip weighted median": a
  // percentile of FLIP's weighted histogram, not of the pixels), and what this value is when its
  // metric reports several. Empty: the name, and the metric's description alone.
  std::string label;
  std::string description;
};

struct MetricInfo {
  std::string name;
  std::string description;
  std::vector<MetricValueInfo> values;  // what it reports, in report order
};

// Every metric, in report order.
const std::vector<MetricInfo>& metricCatalogue();

// The declared value of this name ("relmse", "flip_mean"), or nullptr.
const MetricValueInfo* findMetricValue(std::string_view value_name);

// How far a value is from ideal, in the value's own units: the value for errors, its negation
// for similarities, |value − 1| for ratios. A change is an improvement when it lowers this. A name
// no metric declares (a value of a metric since removed) is taken as an error.
double distanceFromIdeal(std::string_view value_name, double value);

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
