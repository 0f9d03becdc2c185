#include "metrics/error_concentration.h"
#include "metrics/metric_registry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

namespace gib::metrics {
namespace {

image::Image mapOf(const std::vector<float>& values) {
  image::Image map(int(values.size()), 1, 1);
  std::copy(values.begin(), values.end(), map.data().begin());
  return map;
}

// 1000 pixels of error 1 and one of error 1000 (an edge pixel): the worst 0.1 % (one pixel)
// holds half of the sum, and without it the mean is the others' 1.
TEST(ErrorConcentration, OneEdgePixelHoldsItsShareAndTheRestKeepsItsMean) {
  std::vector<float> values(1000, 1.0f);
  values.push_back(1000.0f);
  const ErrorConcentration c = errorConcentration(mapOf(values), 0.001);
  EXPECT_EQ(c.worst, 1u);
  EXPECT_DOUBLE_EQ(c.share, 0.5);
  EXPECT_DOUBLE_EQ(c.mean_without, 1.0);
}

TEST(ErrorConcentration, AnEvenErrorIsNotConcentrated) {
  const ErrorConcentration c = errorConcentration(mapOf(std::vector<float>(2000, 0.25f)), 0.01);
  EXPECT_EQ(c.worst, 20u);
  EXPECT_NEAR(c.share, 0.01, 1e-12);
  EXPECT_DOUBLE_EQ(c.mean_without, 0.25);
}

// NaN pixels are left out, as every metric leaves them out; the result depends on the values,
// not on their order (up to the rounding of a sum in another order).
TEST(ErrorConcentration, IgnoresNanAndTheOrderOfPixels) {
  std::vector<float> values(999);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> uniform(0.0f, 3.0f);
  for (float& v : values) v = uniform(random) * uniform(random) * uniform(random);
  const ErrorConcentration sorted = errorConcentration(mapOf(values), 0.01);
  std::shuffle(values.begin(), values.end(), random);
  values.push_back(std::numeric_limits<float>::quiet_NaN());
  const ErrorConcentration shuffled = errorConcentration(mapOf(values), 0.01);
  EXPECT_EQ(shuffled.worst, 9u);  // floor(0.01 · 999 finite pixels)
  EXPECT_NEAR(shuffled.share, sorted.share, 1e-12);
  EXPECT_NEAR(shuffled.mean_without, sorted.mean_without, 1e-12);
}

// Fewer pixels than one worst pixel: nothing is dropped.
TEST(ErrorConcentration, ASmallImageDropsNothing) {
  const ErrorConcentration c = errorConcentration(mapOf({1.0f, 3.0f}), 0.01);
  EXPECT_EQ(c.worst, 0u);
  EXPECT_EQ(c.share, 0.0);
  EXPECT_DOUBLE_EQ(c.mean_without, 2.0);
}

// relMSE reports its concentration with it: the values the report shows for every comparison.
TEST(ErrorConcentration, RelMseReportsItsConcentration) {
  image::Image reference(100, 20, 3, 1.0f), test(100, 20, 3, 1.1f);
  test.pixel(3, 4)[0] = test.pixel(3, 4)[1] = test.pixel(3, 4)[2] = 11.0f;  // one edge pixel
  const MetricReport report = evaluateMetrics(reference, test, {"relmse"});
  const double pixel = 0.01 / 1.01, edge = 100.0 / 1.01;
  EXPECT_NEAR(report.value("relmse"), (1999 * pixel + edge) / 2000, 1e-6);
  // 0.1 % of 2000 pixels is 2: the edge pixel and one ordinary one.
  EXPECT_NEAR(report.value("relmse_top0p1pct_share"), (edge + pixel) / (1999 * pixel + edge), 1e-6);
  EXPECT_NEAR(report.value("relmse_trim0p1pct"), pixel, 1e-6);
  EXPECT_NEAR(report.value("relmse_trim1pct"), pixel, 1e-6);
  // Without a disagreement mask every pixel counts; with one, its pixels are left out of
  // relmse_agreeing alone.
  EXPECT_EQ(report.value("relmse_agreeing"), report.value("relmse"));
  image::Image mask(100, 20, 1);
  mask.pixel(3, 4)[0] = 1.0f;
  MetricOptions options;
  options.disagreement = &mask;
  const MetricReport masked = evaluateMetrics(reference, test, {"relmse"}, options);
  EXPECT_NEAR(masked.value("relmse_agreeing"), pixel, 1e-6);
  EXPECT_EQ(masked.value("relmse"), report.value("relmse"));
  EXPECT_EQ(findMetricValue("relmse_top1pct_share")->direction, MetricDirection::kDescriptive);
}

// A technique's region (Technique::measuredRegion: its object, its mirrors) gets relMSE over its
// pixels alone, beside the whole image's: the region here is a column with the edge pixel.
TEST(ErrorConcentration, RelMseOverATechniquesRegion) {
  image::Image reference(100, 20, 3, 1.0f), test(100, 20, 3, 1.1f);
  for (int y = 0; y < 20; ++y)
    for (int c = 0; c < 3; ++c) test.pixel(3, y)[c] = 2.0f;
  const MetricReport whole = evaluateMetrics(reference, test, {"relmse"});
  EXPECT_EQ(whole.value("relmse_region"), whole.value("relmse"));
  image::Image region(100, 20, 1);
  for (int y = 0; y < 20; ++y) region.pixel(3, y)[0] = 1.0f;
  MetricOptions options;
  options.region = &region;
  const MetricReport masked = evaluateMetrics(reference, test, {"relmse"}, options);
  EXPECT_NEAR(masked.value("relmse_region"), 1.0 / 1.01, 1e-6);
  EXPECT_EQ(masked.value("relmse"), whole.value("relmse"));
  EXPECT_EQ(findMetricValue("relmse_region")->direction, MetricDirection::kLowerIsBetter);
  EXPECT_EQ(distanceFromIdeal("relmse_top1pct_share", 0.9), 0.0);
}

}  // namespace
}  // namespace gib::metrics
