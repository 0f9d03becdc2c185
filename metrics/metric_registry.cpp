#include "metrics/metric_registry.h"

#include "common/input_error.h"
#include "common/join.h"
#include "metrics/error_concentration.h"
#include "metrics/mean_bias.h"
#include "metrics/ssim.h"

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <stdexcept>

namespace gib::metrics {

namespace {

using Evaluator = std::function<void(const image::Image&, const image::Image&, const MetricOptions&,
                                     MetricReport&)>;

struct MetricEntry {
  MetricInfo info;
  Evaluator evaluate;
};

constexpr MetricDirection kLower = MetricDirection::kLowerIsBetter;
constexpr MetricDirection kHigher = MetricDirection::kHigherIsBetter;

// The values of one figure named like its metric.
std::vector<MetricValueInfo> single(const char* name, MetricDirection direction = kLower) {
  return {{.name = name, .direction = direction, .label = {}, .description = {}}};
}

// FLIP's values (addFlip), all errors.
// The median and quartiles are those of FLIP's weighted histogram (metrics/flip.h: each pixel
// weighted by its error), not the pixels' own percentiles.
std::vector<MetricValueInfo> flipValues(const std::string& prefix) {
  struct Value {
    const char* suffix;
    const char* label;
    const char* description;
  };
  static constexpr Value kValues[] = {
      {"_mean", "mean", "the mean of the per-pixel FLIP map"},
      {"_median", "weighted median",
       "the median of FLIP's weighted histogram (pixels weighted by their error), not of the "
       "pixels"},
      {"_q1", "weighted first quartile",
       "the first quartile of FLIP's weighted histogram (pixels weighted by their error)"},
      {"_q3", "weighted third quartile",
       "the third quartile of FLIP's weighted histogram (pixels weighted by their error)"},
      {"_max", "max", "the largest per-pixel FLIP value"},
  };
  std::vector<MetricValueInfo> values;
  for (const Value& v : kValues)
    values.push_back({.name = prefix + v.suffix,
                      .direction = kLower,
                      .label = prefix + " " + v.label,
                      .description = v.description});
  return values;
}

// A metric with one figure and a map under its own name.
Evaluator scalar(
    const char* name,
    std::function<MetricValue(const image::Image&, const image::Image&, const MetricOptions&)>
        compute) {
  return [name, compute](const image::Image& r, const image::Image& t, const MetricOptions& o,
                         MetricReport& report) {
    MetricValue v = compute(r, t, o);
    report.values.emplace_back(name, v.value);
    if (v.map.pixelCount() > 0) report.maps.emplace_back(name, std::move(v.map));
  };
}

// The fractions of worst pixels whose share of relMSE is reported, and the names of the values.
struct ConcentrationFigure {
  double fraction;
  const char* percent;  // "0.1 %", for people
  const char* share;    // the worst pixels' share of the sum
  const char* without;  // relMSE of the other pixels
};
constexpr ConcentrationFigure kConcentrationFigures[] = {
    {0.001, "0.1 %", "relmse_top0p1pct_share", "relmse_trim0p1pct"},
    {0.01, "1 %", "relmse_top1pct_share", "relmse_trim1pct"},
};

std::vector<MetricValueInfo> relMseValues() {
  std::vector<MetricValueInfo> values = {
      {.name = "relmse", .direction = kLower, .label = {}, .description = {}}};
  for (const ConcentrationFigure& f : kConcentrationFigures)
    values.push_back(
        {.name = f.share,
         .direction = MetricDirection::kDescriptive,
         .label = fmt::format("relmse share of worst {}", f.percent),
         .description = fmt::format("the share of relMSE's sum held by the worst {} of pixels (by "
                                    "per-pixel relMSE): how concentrated the error is",
                                    f.percent)});
  for (const ConcentrationFigure& f : kConcentrationFigures)
    values.push_back(
        {.name = f.without,
         .direction = kLower,
         .label = fmt::format("relmse without worst {}", f.percent),
         .description = fmt::format("relMSE over the pixels other than the worst {}", f.percent)});
  values.push_back({.name = "relmse_agreeing",
                    .direction = kLower,
                    .label = "relmse where hits agree",
                    .description = "relMSE over the pixels where the technique's rasteriser and "
                                   "the reference's camera ray see the same surface (all pixels "
                                   "when not checked)"});
  values.push_back({.name = "relmse_region",
                    .direction = kLower,
                    .label = "relmse over the technique's region",
                    .description = "relMSE over the pixels the technique names as what its own "
                                   "light reaches (a gathered object, the mirrors and glass), "
                                   "without the shared direct light elsewhere (all pixels when "
                                   "it names none)"});
  return values;
}

// The mean of a one-channel map's finite values where `mask` is 0 (`inside` false) or non-zero
// (`inside` true).
double maskedMean(const image::Image& map, const image::Image& mask, bool inside) {
  if (mask.width() != map.width() || mask.height() != map.height() || mask.channels() != 1)
    throw std::invalid_argument("a metric's pixel mask must be one channel of the images' size");
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < map.data().size(); ++i)
    if ((mask.data()[i] != 0) == inside && std::isfinite(map.data()[i])) {
      sum += map.data()[i];
      ++count;
    }
  return count > 0 ? sum / double(count) : 0.0;
}

// relMSE, its map, and how concentrated it is (metrics/error_concentration.h), in the order of
// relMseValues.
void addRelMse(const image::Image& r, const image::Image& t, const MetricOptions& o,
               MetricReport& report) {
  MetricValue relmse = computeRelMse(r, t, o.relative_epsilon, o.reject_outliers);
  report.values.emplace_back("relmse", relmse.value);
  std::vector<double> fractions;
  for (const ConcentrationFigure& f : kConcentrationFigures) fractions.push_back(f.fraction);
  const std::vector<ErrorConcentration> concentration = errorConcentrations(relmse.map, fractions);
  for (std::size_t i = 0; i < concentration.size(); ++i)
    report.values.emplace_back(kConcentrationFigures[i].share, concentration[i].share);
  for (std::size_t i = 0; i < concentration.size(); ++i)
    report.values.emplace_back(kConcentrationFigures[i].without, concentration[i].mean_without);
  report.values.emplace_back("relmse_agreeing", o.disagreement
                                                    ? maskedMean(relmse.map, *o.disagreement, false)
                                                    : relmse.value);
  report.values.emplace_back("relmse_region",
                             o.region ? maskedMean(relmse.map, *o.region, true) : relmse.value);
  report.maps.emplace_back("relmse", std::move(relmse.map));
}

// FLIP's figures: the mean, the weighted median and quartiles, the maximum, and the map.
void addFlip(const std::string& prefix, FlipResult flip, MetricReport& report) {
  report.values.emplace_back(prefix + "_mean", flip.mean);
  report.values.emplace_back(prefix + "_median", flip.weighted_median);
  report.values.emplace_back(prefix + "_q1", flip.weighted_first_quartile);
  report.values.emplace_back(prefix + "_q3", flip.weighted_third_quartile);
  report.values.emplace_back(prefix + "_max", flip.maximum);
  report.maps.emplace_back(prefix, std::move(flip.error_map));
}

const std::vector<MetricEntry>& entries() {
  static const std::vector<MetricEntry> table = {
      {{"mse", "mean squared error of linear RGB", single("mse")},
       scalar("mse", [](auto& r, auto& t, auto&) { return computeMse(r, t); })},
      {{"rmse", "root mean squared error of linear RGB", single("rmse")},
       scalar("rmse", [](auto& r, auto& t, auto&) { return computeRmse(r, t); })},
      {{"mae", "mean absolute error of linear RGB", single("mae")},
       scalar("mae", [](auto& r, auto& t, auto&) { return computeMae(r, t); })},
      {{"relmse",
        "relative MSE (x-r)^2/(r^2+eps), eps = 0.01; --reject-outliers drops the top 0.1%; with "
        "how concentrated it is: the share held by the worst 0.1% and 1% of pixels, relMSE "
        "without them, and relMSE without the pixels whose primary hit the technique and the "
        "reference disagree on (relmse_agreeing; all pixels when not checked)",
        relMseValues()},
       addRelMse},
      {{"mape", "mean absolute percentage error |x-r|/(|r|+eps)", single("mape")},
       scalar("mape",
              [](auto& r, auto& t, auto& o) { return computeMape(r, t, o.relative_epsilon); })},
      {{"smape", "symmetric MAPE 2|x-r|/(|x|+|r|+eps)", single("smape")},
       scalar("smape",
              [](auto& r, auto& t, auto& o) { return computeSmape(r, t, o.relative_epsilon); })},
      {{"psnr", "PSNR in dB after clamping to [0,1] and the sRGB curve", single("psnr", kHigher)},
       scalar("psnr", [](auto& r, auto& t, auto&) { return computePsnr(r, t); })},
      {{"energy",
        "energy_ratio: mean luminance of the image over the reference's (1 = no light "
        "lost or gained)",
        single("energy_ratio", MetricDirection::kTowardOne)},
       scalar("energy_ratio", [](auto& r, auto& t, auto&) { return computeEnergyRatio(r, t); })},
      {{"block_bias",
        "largest relative difference of a channel's 16x16 block means (blocks under 1% of the "
        "image mean left out): bias that pixel noise hides",
        single("block_bias")},
       scalar("block_bias", [](auto& r, auto& t, auto&) { return computeBlockBias(r, t); })},
      {{"ssim", "SSIM of display luminance (11x11 Gaussian window, sigma 1.5)",
        single("ssim", kHigher)},
       scalar("ssim", [](auto& r, auto& t, auto&) { return computeSsim(r, t); })},
      {{"flip", "LDR-FLIP (Andersson et al. 2020): mean, weighted median and quartiles, max",
        flipValues("flip")},
       [](auto& r, auto& t, auto& o, MetricReport& report) {
         addFlip("flip", computeLdrFlip(r, t, o.flip), report);
       }},
      {{"hdrflip", "HDR-FLIP (Andersson et al. 2021): mean, weighted median and quartiles, max",
        flipValues("hdrflip")},
       [](auto& r, auto& t, auto& o, MetricReport& report) {
         addFlip("hdrflip", computeHdrFlip(r, t, o.flip), report);
       }},
  };
  return table;
}

}  // namespace

const std::vector<MetricInfo>& metricCatalogue() {
  static const std::vector<MetricInfo> infos = [] {
    std::vector<MetricInfo> result;
    for (const MetricEntry& e : entries()) result.push_back(e.info);
    return result;
  }();
  return infos;
}

const MetricValueInfo* findMetricValue(std::string_view value_name) {
  for (const MetricEntry& e : entries())
    for (const MetricValueInfo& value : e.info.values)
      if (value.name == value_name) return &value;
  return nullptr;
}

double distanceFromIdeal(std::string_view value_name, double value) {
  const MetricValueInfo* info = findMetricValue(value_name);
  switch (info ? info->direction : kLower) {
    case MetricDirection::kLowerIsBetter:
      return value;
    case MetricDirection::kHigherIsBetter:
      return -value;
    case MetricDirection::kTowardOne:
      return std::abs(value - 1.0);
    case MetricDirection::kDescriptive:
      return 0.0;
  }
  return value;
}

std::vector<std::string> parseMetricList(std::string_view list) {
  std::vector<std::string> names;
  if (list == "all") {
    for (const MetricEntry& e : entries()) names.push_back(e.info.name);
    return names;
  }
  std::size_t start = 0;
  while (start <= list.size()) {
    std::size_t end = std::min(list.find(',', start), list.size());
    std::string name(list.substr(start, end - start));
    bool known = false;
    for (const MetricEntry& e : entries()) known = known || e.info.name == name;
    if (!known) {
      const std::string all =
          joinNames(entries(), ", ", [](const MetricEntry& e) { return e.info.name; });
      throw InputError(fmt::format(
          "unknown metric '{}'; choose 'all' or a comma-separated list of: {}", name, all));
    }
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    start = end + 1;
  }
  return names;
}

double MetricReport::value(std::string_view name) const {
  for (const auto& [key, v] : values)
    if (key == name) return v;
  throw std::out_of_range(fmt::format("no figure '{}' in the metric report", name));
}

MetricReport evaluateMetrics(const image::Image& reference, const image::Image& test,
                             const std::vector<std::string>& names, const MetricOptions& options) {
  requireComparable(reference, test);
  MetricReport report;
  report.nonfinite_pixels = image::countNonFinite(test);
  // Report order is the catalogue's, whatever order the names came in.
  for (const MetricEntry& e : entries())
    if (std::find(names.begin(), names.end(), e.info.name) != names.end())
      e.evaluate(reference, test, options, report);
  return report;
}

}  // namespace gib::metrics
