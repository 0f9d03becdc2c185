#include "reports/chart_axes.h"

#include <gtest/gtest.h>

namespace gib::reports {
namespace {

std::vector<std::string> labels(const Axis& axis) {
  std::vector<std::string> out;
  for (const Tick& tick : axis.ticks)
    if (!tick.label.empty()) out.push_back(tick.label);
  return out;
}

TEST(ChartAxes, LinearAxisWidensToRoundTicks) {
  const Axis axis = linearAxis(0.3, 9.2);
  EXPECT_EQ(axis.low, 0);
  EXPECT_EQ(axis.high, 10);
  EXPECT_EQ(labels(axis), (std::vector<std::string>{"0", "2", "4", "6", "8", "10"}));
}

TEST(ChartAxes, LinearTicksOfSmallStepsHaveNoRoundingNoise) {
  const Axis axis = linearAxis(0.1, 0.7, 6);  // step 0.1: 3 · 0.1 is 0.30000000000000004
  EXPECT_EQ(labels(axis),
            (std::vector<std::string>{"0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.7"}));
}

TEST(ChartAxes, DegenerateLinearRangeIsWidenedAroundItsValue) {
  const Axis zero = linearAxis(0, 0);
  EXPECT_LT(zero.low, 0);
  EXPECT_GT(zero.high, 0);
  const Axis five = linearAxis(5, 5);
  EXPECT_LT(five.low, 5);
  EXPECT_GT(five.high, 5);
  EXPECT_GE(five.ticks.size(), 2u);
}

TEST(ChartAxes, LogAxisCoversWholeDecadesWithMinorTicks) {
  const Axis axis = logAxis(0.003, 0.4);
  EXPECT_TRUE(axis.log);
  EXPECT_DOUBLE_EQ(axis.low, 0.001);
  EXPECT_DOUBLE_EQ(axis.high, 1);
  EXPECT_EQ(labels(axis), (std::vector<std::string>{"0.001", "0.01", "0.1", "1"}));
  EXPECT_EQ(axis.ticks.size(), 4u + 3u * 8u);  // 2..9 in each of three decades
}

TEST(ChartAxes, LogAxisOfOneValueSpansADecade) {
  const Axis axis = logAxis(10, 10);
  EXPECT_DOUBLE_EQ(axis.low, 10);
  EXPECT_DOUBLE_EQ(axis.high, 100);
}

TEST(ChartAxes, ManyDecadesAreLabelledWithAStride) {
  const Axis axis = logAxis(1e-6, 1e8);
  const std::vector<std::string> text = labels(axis);
  EXPECT_LE(text.size(), 8u);
  EXPECT_EQ(text.front(), "1e-6");
  EXPECT_EQ(text[1], "1e-4");
  EXPECT_EQ(text[3], "1");
}

TEST(ChartAxes, PixelsMapLinearlyAndLogarithmically) {
  const Axis linear = linearAxis(0, 10);
  EXPECT_DOUBLE_EQ(axisPixel(linear, 5, 100, 200), 150);
  const Axis log = logAxis(1, 100);
  EXPECT_DOUBLE_EQ(axisPixel(log, 10, 0, 100), 50);
  EXPECT_DOUBLE_EQ(axisPixel(log, 100, 300, 0), 0);  // a y axis runs upwards
}

}  // namespace
}  // namespace gib::reports
