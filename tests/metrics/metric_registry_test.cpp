// The metric registry declares every value a metric reports and which way it improves: the diff,
// the report's colours and suite tolerances read these declarations, so they must match what
// the evaluators actually emit.
#include "metrics/metric_registry.h"

#include "common/input_error.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace gib::metrics {
namespace {

image::Image gradient(int width, int height, float scale) {
  image::Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) image.pixel(x, y)[c] = scale * float(x + y + c + 1) / 40.0f;
  return image;
}

TEST(MetricRegistry, DeclaresExactlyTheValuesTheEvaluatorsReport) {
  const MetricReport report =
      evaluateMetrics(gradient(24, 16, 1.0f), gradient(24, 16, 1.1f), parseMetricList("all"));
  std::vector<std::string> reported, declared;
  for (const auto& [name, value] : report.values) reported.push_back(name);
  for (const MetricInfo& info : metricCatalogue())
    for (const MetricValueInfo& value : info.values) declared.push_back(value.name);
  EXPECT_EQ(reported, declared);  // same names, same order
  for (const std::string& name : reported) EXPECT_NE(findMetricValue(name), nullptr) << name;
}

TEST(MetricRegistry, EachValueKnowsWhichWayIsBetter) {
  EXPECT_EQ(findMetricValue("relmse")->direction, MetricDirection::kLowerIsBetter);
  EXPECT_EQ(findMetricValue("flip_q3")->direction, MetricDirection::kLowerIsBetter);
  EXPECT_EQ(findMetricValue("psnr")->direction, MetricDirection::kHigherIsBetter);
  EXPECT_EQ(findMetricValue("ssim")->direction, MetricDirection::kHigherIsBetter);
  EXPECT_EQ(findMetricValue("energy_ratio")->direction, MetricDirection::kTowardOne);
  EXPECT_EQ(findMetricValue("flip"), nullptr);  // a metric's name, not one of its values
  EXPECT_EQ(findMetricValue("psnr_mean"), nullptr);
}

TEST(MetricRegistry, DistanceFromIdealFollowsTheDirection) {
  EXPECT_LT(distanceFromIdeal("relmse", 0.01), distanceFromIdeal("relmse", 0.02));
  EXPECT_LT(distanceFromIdeal("psnr", 40), distanceFromIdeal("psnr", 30));
  EXPECT_LT(distanceFromIdeal("energy_ratio", 0.99), distanceFromIdeal("energy_ratio", 1.05));
  EXPECT_LT(distanceFromIdeal("energy_ratio", 1.01), distanceFromIdeal("energy_ratio", 0.95));
  // A value no metric declares any more (an old results file) is read as an error.
  EXPECT_LT(distanceFromIdeal("retired_metric", 1), distanceFromIdeal("retired_metric", 2));
}

TEST(MetricRegistry, UnknownNamesListTheKnownOnes) {
  try {
    parseMetricList("relmse,flop");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown metric 'flop'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace gib::metrics
