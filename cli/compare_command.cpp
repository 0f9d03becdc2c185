// gibench compare REFERENCE.exr TEST.exr [--metrics all|name,...] [--maps DIR] [--json]
#include "cli/commands.h"
#include "common/input_error.h"
#include "gib/version.h"
#include "image/display.h"
#include "image/exr_io.h"
#include "metrics/error_map_display.h"
#include "metrics/mean_bias.h"
#include "metrics/metric_registry.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <memory>

namespace gib::cli {

namespace {

namespace fs = std::filesystem;

struct CompareOptions {
  std::string reference;
  std::string test;
  std::string metrics = "all";
  std::string maps;
  bool json = false;
  double pixels_per_degree = 67.0;
  double epsilon = metrics::kRelativeEpsilon;
  bool reject_outliers = false;
};

void writeMaps(const fs::path& dir, const metrics::MetricReport& report,
               const image::Metadata& metadata) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (!fs::is_directory(dir))
    throw InputError(
        fmt::format("cannot create the maps directory '{}'; choose another --maps", dir.string()));
  for (const auto& [name, map] : report.maps) {
    image::Metadata m = metadata;
    m["gibench/metric"] = name;
    image::writeExr(dir / (name + ".exr"), {{name, map}}, m);
    image::writePng(dir / (name + ".png"), metrics::errorMapForDisplay(name, map));
  }
}

int runCompare(const CompareOptions& o) {
  const std::vector<std::string> names = metrics::parseMetricList(o.metrics);
  if (!(o.pixels_per_degree > 0))
    throw InputError("--ppd must be positive (67 is a 0.7 m wide 4K monitor seen from 0.7 m)");
  if (!(o.epsilon > 0)) throw InputError("--epsilon must be positive");
  // By channel name, so RGBA files (Blender's, other renderers') compare like RGB ones.
  const image::Image reference = image::readRgb(o.reference);
  const image::Image test = image::readRgb(o.test);
  if (reference.width() != test.width() || reference.height() != test.height())
    throw InputError(fmt::format(
        "reference is {}x{} but test is {}x{}; render both at the same --width and --height",
        reference.width(), reference.height(), test.width(), test.height()));
  if (std::size_t bad = image::countNonFinite(reference); bad > 0)
    throw InputError(fmt::format("reference '{}' has {} NaN or infinite pixels; re-render it",
                                 o.reference, bad));
  if (!o.maps.empty() && fs::exists(o.maps) && !fs::is_directory(o.maps))
    throw InputError(fmt::format("--maps '{}' is a file; give a directory", o.maps));

  metrics::MetricOptions options;
  options.flip.pixels_per_degree = o.pixels_per_degree;
  options.relative_epsilon = o.epsilon;
  options.reject_outliers = o.reject_outliers;
  const metrics::MetricReport report = metrics::evaluateMetrics(reference, test, names, options);
  // Beside the metrics: two renderers agree on a scene only if these agree (metrics/mean_bias.h).
  const metrics::ChannelMeans means = metrics::computeChannelMeans(reference, test);

  if (!o.maps.empty()) {
    image::Metadata metadata = {{"gibench/program", kProgramName},
                                {"gibench/version", kVersion},
                                {"gibench/reference", o.reference},
                                {"gibench/test", o.test}};
    writeMaps(o.maps, report, metadata);
  }

  if (o.json) {
    nlohmann::ordered_json j;
    for (const auto& [name, value] : report.values)
      j["metrics"][name] = std::isfinite(value) ? nlohmann::ordered_json(value)
                                                : nlohmann::ordered_json(fmt::format("{}", value));
    j["nonfinite"] = report.nonfinite_pixels;
    j["means"] = {{"reference", means.reference}, {"test", means.test}};
    j["width"] = reference.width();
    j["height"] = reference.height();
    j["reference"] = o.reference;
    j["test"] = o.test;
    j["pixels_per_degree"] = o.pixels_per_degree;
    j["version"] = kVersion;
    fmt::print("{}\n", j.dump());
    return 0;
  }
  fmt::print("{:<16} {}\n", "metric", "value");
  for (const auto& [name, value] : report.values) fmt::print("{:<16} {:.6g}\n", name, value);
  fmt::print("{:<16} {}\n", "nonfinite", report.nonfinite_pixels);
  fmt::print("{:<16} {:.6g} {:.6g} {:.6g}\n", "reference mean", means.reference[0],
             means.reference[1], means.reference[2]);
  fmt::print("{:<16} {:.6g} {:.6g} {:.6g}\n", "test mean", means.test[0], means.test[1],
             means.test[2]);
  if (!o.maps.empty()) fmt::print("maps in {}\n", o.maps);
  return 0;
}

}  // namespace

CommandRunner addCompareCommand(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* compare = app.add_subcommand("compare", "Measure a test image against a reference");
  compare->add_option("reference", o->reference, "reference EXR")->required();
  compare->add_option("test", o->test, "test EXR")->required();
  compare
      ->add_option("--metrics", o->metrics, "all, or a comma-separated list (gibench list metrics)")
      ->capture_default_str();
  compare->add_option("--maps", o->maps,
                      "write per-pixel error maps (EXR and false-colour PNG) here");
  compare->add_flag("--json", o->json, "print one JSON object instead of a table");
  compare->add_option("--ppd", o->pixels_per_degree, "FLIP viewing condition: pixels per degree")
      ->capture_default_str();
  compare->add_option("--epsilon", o->epsilon, "epsilon of relmse, mape and smape")
      ->capture_default_str();
  compare->add_flag("--reject-outliers", o->reject_outliers,
                    "relmse without the largest 0.1% of pixel values");
  return [o] { return runCompare(*o); };
}

}  // namespace gib::cli
