#include "reports/svg_charts.h"

#include "image/false_color.h"
#include "support/markup_check.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <limits>

namespace gib::reports {
namespace {

using test::countOccurrences;
using test::markupProblem;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// A chart must never carry a non-finite number: browsers drop the element silently.
void expectNoNonFinite(const std::string& svg) {
  std::string lower = svg;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  EXPECT_EQ(lower.find("nan"), std::string::npos) << svg;
  EXPECT_EQ(lower.find("inf"), std::string::npos) << svg;
}

void expectWellFormedChart(const std::string& svg) {
  EXPECT_EQ(markupProblem(svg), "") << svg;
  EXPECT_EQ(svg.rfind("<svg class=\"chart\"", 0), 0u) << svg;
  EXPECT_NE(svg.find("viewBox=\"0 0 "), std::string::npos);
  expectNoNonFinite(svg);
}

std::vector<PassBar> threePasses() {
  return {{"frame", 0, 20, 19, 21}, {"shadow_maps", 1, 6, 5.5, 6.5}, {"cube_faces", 2, 5, 4, 6}};
}

TEST(SvgCharts, PassChartHasOneBarAndOneWhiskerPerPassWithNamesAndAxis) {
  const std::string svg = passTimingChart(threePasses());
  expectWellFormedChart(svg);
  // One <rect> per bar (each with a tooltip), one whisker <path> per pass.
  EXPECT_EQ(countOccurrences(svg, "<rect "), 3);
  EXPECT_EQ(countOccurrences(svg, "<path "), 3);
  for (const char* name : {">frame<", ">shadow_maps<", ">cube_faces<", ">20 ms<"})
    EXPECT_NE(svg.find(name), std::string::npos) << name;
  EXPECT_NE(svg.find("ms per frame: median, whiskers from first to third quartile"),
            std::string::npos);
  // Nesting: deeper names start further right (x of the label text).
  const auto x_of = [&](const std::string& name) {
    const std::size_t at = svg.find(">" + name + "<");
    const std::size_t x = svg.rfind("<text x=\"", at);
    return std::stod(svg.substr(x + 9));
  };
  EXPECT_LT(x_of("frame"), x_of("shadow_maps"));
  EXPECT_LT(x_of("shadow_maps"), x_of("cube_faces"));
}

TEST(SvgCharts, PassChartSkipsNonFiniteTimesWithANote) {
  std::vector<PassBar> passes = threePasses();
  passes[1].median_ms = kNaN;
  passes[2].third_quartile_ms = kInf;  // bar drawn, whisker dropped
  const std::string svg = passTimingChart(passes);
  expectWellFormedChart(svg);
  EXPECT_EQ(countOccurrences(svg, "<rect "), 2);
  EXPECT_EQ(countOccurrences(svg, "<path "), 1);
  EXPECT_NE(svg.find("passes without a finite time not shown: 1"), std::string::npos);
  EXPECT_EQ(svg.find(">shadow_maps<"), std::string::npos);
}

TEST(SvgCharts, PassChartOfZeroTimesAndOfNoPassesIsDrawable) {
  const std::string zeros = passTimingChart({{"frame", 0, 0, 0, 0}});
  expectWellFormedChart(zeros);
  EXPECT_EQ(countOccurrences(zeros, "<rect "), 1);
  const std::string none = passTimingChart({});
  expectWellFormedChart(none);
  EXPECT_NE(none.find("no finite pass times"), std::string::npos);
}

LogLogPlot convergencePlot() {
  LogLogPlot plot{"Convergence of relmse", "spp", "relmse", {}, FittedSlope{-0.98, 0.03}};
  for (double x : {1.0, 4.0, 16.0, 64.0, 256.0}) plot.points.emplace_back(x, 0.5 / x);
  return plot;
}

TEST(SvgCharts, ConvergenceChartHasOnePointPerPointTheFittedLineAndItsSlope) {
  const std::string svg = logLogChart(convergencePlot());
  expectWellFormedChart(svg);
  EXPECT_EQ(countOccurrences(svg, "<circle "), 5);
  EXPECT_EQ(countOccurrences(svg, "stroke-dasharray"), 1);  // the fitted line
  EXPECT_NE(svg.find("slope \u22120.98 \u00b1 0.03"), std::string::npos) << svg;
  EXPECT_NE(svg.find(">spp<"), std::string::npos);
  EXPECT_NE(svg.find(">relmse<"), std::string::npos);
}

TEST(SvgCharts, LogAxesAreLabelledAtDecades) {
  const std::string svg = logLogChart(convergencePlot());
  // x from 1 to 256: decades 1, 10, 100, 1000; y from 0.5/256 ≈ 0.002 to 0.5: 0.001 … 1.
  for (const char* label : {">1<", ">10<", ">100<", ">1000<", ">0.001<", ">0.01<", ">0.1<"})
    EXPECT_NE(svg.find(label), std::string::npos) << label;
  EXPECT_EQ(svg.find(">2<"), std::string::npos);  // minor ticks are not labelled
}

TEST(SvgCharts, ConvergenceChartOfOnePointZerosAndNonFiniteValuesHasNoNaN) {
  LogLogPlot plot{"one", "spp", "relmse", {{16, 0.01}}, FittedSlope{-1, 0.1}};
  std::string svg = logLogChart(plot);
  expectWellFormedChart(svg);
  EXPECT_EQ(countOccurrences(svg, "<circle "), 1);
  EXPECT_EQ(svg.find("stroke-dasharray"), std::string::npos);  // no line through one point

  plot.points = {{16, 0.01}, {64, 0}, {256, kNaN}, {kInf, 0.1}, {1024, 0.001}};
  svg = logLogChart(plot);
  expectWellFormedChart(svg);
  EXPECT_EQ(countOccurrences(svg, "<circle "), 2);
  EXPECT_NE(svg.find("points with zero or non-finite values not shown: 3"), std::string::npos);

  plot.points = {{1, 0}, {2, 0}};
  svg = logLogChart(plot);
  expectWellFormedChart(svg);
  EXPECT_NE(svg.find("no point with positive values"), std::string::npos);
}

TEST(SvgCharts, SlopeWithoutAnIntervalIsShownWithoutOne) {
  LogLogPlot plot = convergencePlot();
  plot.fit->ci95 = kInf;  // two points
  const std::string svg = logLogChart(plot);
  expectWellFormedChart(svg);
  // The label names what was fitted: the plot's y quantity.
  EXPECT_NE(svg.find(">relmse: slope \u22120.98<"), std::string::npos) << svg;
}

// The x coordinate of the element that starts at `at` ("cx" of a circle, "x1" of a line).
double coordinateAfter(const std::string& svg, std::size_t at, const std::string& name) {
  const std::size_t start = svg.find(name + "=\"", at);
  return std::stod(svg.substr(start + name.size() + 2));
}

TEST(SvgCharts, StripChartHasADotPerSampleAndAMedianBarPerRow) {
  const StripPlot plot{"Each frame's time per pass",
                       "frame",
                       "ms",
                       {{"frame", 0, {20, 21, 19, 20, 95}}, {"shading", 1, {10, 12, 11}}}};
  const std::string svg = stripChart(plot);
  expectWellFormedChart(svg);
  EXPECT_EQ(countOccurrences(svg, "<circle "), 8);
  // The outlier has a dot of its own, named by frame, pass and unit, furthest right.
  const std::size_t outlier = svg.find("<title>frame 5, frame: 95 ms</title>");
  ASSERT_NE(outlier, std::string::npos) << svg;
  const std::size_t typical = svg.find("<title>frame 1, frame: 20 ms</title>");
  ASSERT_NE(typical, std::string::npos) << svg;
  const double outlier_x = coordinateAfter(svg, svg.rfind("<circle ", outlier), "cx");
  const double typical_x = coordinateAfter(svg, svg.rfind("<circle ", typical), "cx");
  EXPECT_GT(outlier_x, typical_x + 100);
  // A median bar per row, the first at 20 ms (not pulled right by the outlier, as a mean is).
  const std::string bar = R"(stroke="#c0392b" stroke-width="2")";
  EXPECT_EQ(countOccurrences(svg, bar), 2);
  const std::size_t first_bar = svg.rfind("<line ", svg.find(bar));
  EXPECT_NEAR(coordinateAfter(svg, first_bar, "x1"), typical_x, 0.05);
  EXPECT_NE(svg.find("ms per frame"), std::string::npos);
}

TEST(SvgCharts, StripChartSkipsNonFiniteSamplesWithANote) {
  const std::string svg = stripChart(
      {"Each iteration's time", "iteration", "\u00b5s", {{"iteration", 0, {kNaN, 5, kInf}}}});
  expectWellFormedChart(svg);
  EXPECT_EQ(countOccurrences(svg, "<circle "), 1);
  EXPECT_NE(svg.find("samples without a finite time not shown: 2"), std::string::npos) << svg;
  EXPECT_NE(svg.find("<title>iteration 2, iteration: 5 \u00b5s</title>"), std::string::npos);
}

TEST(SvgCharts, TrendChartHasOnePointPerRunWithCommitLabelsAndTheRunHighlighted) {
  const std::vector<TrendPoint> runs = {
      {"a1b2c3d", 0.010}, {"b2c3d4e", 0.012}, {"c3d4e5f*", 0.011}};
  const std::string svg = trendChart("relmse over the last 3 runs", "relmse", runs);
  expectWellFormedChart(svg);
  EXPECT_EQ(countOccurrences(svg, "<circle "), 3);
  EXPECT_EQ(countOccurrences(svg, "<polyline "), 1);
  for (const char* label : {">a1b2c3d<", ">b2c3d4e<", ">c3d4e5f*<", "this run, c3d4e5f*: 0.011"})
    EXPECT_NE(svg.find(label), std::string::npos) << label;
  EXPECT_EQ(countOccurrences(svg, "fill=\"#c0392b\""), 1);
}

TEST(SvgCharts, TrendChartOfConstantAndNonFiniteValuesHasNoNaN) {
  std::string svg = trendChart("flat", "ms", {{"a", 5}, {"b", 5}});
  expectWellFormedChart(svg);
  EXPECT_EQ(countOccurrences(svg, "<circle "), 2);

  svg = trendChart("gaps", "ms", {{"a", kNaN}, {"b", 0}, {"c", kInf}, {"d", 0}});
  expectWellFormedChart(svg);
  EXPECT_EQ(countOccurrences(svg, "<circle "), 2);
  EXPECT_NE(svg.find("runs without a finite value not shown: 2"), std::string::npos);

  svg = trendChart("one", "ms", {{"a", 1}});
  expectWellFormedChart(svg);
  EXPECT_EQ(svg.find("<polyline "), std::string::npos);
}

TEST(SvgCharts, ColorBarIsTheMagmaMapOfTheFlipPngsFromZeroToOne) {
  const std::string svg = flipColorBar();
  expectWellFormedChart(svg);
  EXPECT_EQ(countOccurrences(svg, "<stop "), 9);
  for (float t : {0.0f, 0.5f, 1.0f}) {
    float rgb[3];
    image::magmaSrgb(t, rgb);
    const std::string hex =
        fmt::format("#{:02x}{:02x}{:02x}", int(std::lround(rgb[0] * 255)),
                    int(std::lround(rgb[1] * 255)), int(std::lround(rgb[2] * 255)));
    EXPECT_NE(svg.find(fmt::format("offset=\"{}\" stop-color=\"{}\"", t, hex)), std::string::npos)
        << t << " " << hex;
  }
  EXPECT_NE(svg.find(">0<"), std::string::npos);
  EXPECT_NE(svg.find(">1<"), std::string::npos);
}

TEST(SvgCharts, TextIsEscaped) {
  const std::string svg = trendChart("a <b> & \"c\"", "y<x", {{"<tag>", 1}, {"x&y", 2}});
  expectWellFormedChart(svg);
  EXPECT_NE(svg.find("a &lt;b&gt; &amp; &quot;c&quot;"), std::string::npos);
  EXPECT_NE(svg.find("&lt;tag&gt;"), std::string::npos);
  EXPECT_EQ(svg.find("<tag>"), std::string::npos);
}

TEST(SvgCharts, ParetoFrontKeepsThePointsNoOtherBeatsInBothCoordinates) {
  // (time, error): (1, 9) and (2, 4) and (5, 1) are on the front; (3, 6) is beaten by (2, 4),
  // (6, 2) by (5, 1), and (2, 5) by (2, 4).
  const std::vector<std::pair<double, double>> points = {{3, 6}, {1, 9}, {6, 2},
                                                         {2, 4}, {5, 1}, {2, 5}};
  const std::vector<std::size_t> front = paretoFront(points);
  EXPECT_EQ(front, (std::vector<std::size_t>{1, 3, 4}));
  EXPECT_TRUE(paretoFront({}).empty());
}

SeriesPlot twoSeriesPlot() {
  SeriesPlot plot;
  plot.title = "Time per iteration";
  plot.x_label = "vertices";
  plot.y_label = "ms per iteration";
  plot.series = {{"selection = gpu", {{30, 2, "a"}, {3000, 5, "b"}, {300, 3, "c"}}},
                 {"selection = cpu", {{30, 20, "d"}, {3000, 24, "e"}}}};
  return plot;
}

TEST(SvgCharts, SeriesChartDrawsEachSeriesAsALineWithALegend) {
  const std::string svg = seriesChart(twoSeriesPlot());
  expectWellFormedChart(svg);
  EXPECT_EQ(countOccurrences(svg, "<circle "), 5);
  EXPECT_EQ(countOccurrences(svg, "<polyline "), 2);
  EXPECT_NE(svg.find(">selection = gpu<"), std::string::npos);
  EXPECT_NE(svg.find(">selection = cpu<"), std::string::npos);
  EXPECT_EQ(svg.find("Pareto"), std::string::npos);
}

TEST(SvgCharts, SeriesChartOnLogAxesDropsWhatTheyCannotShowWithANote) {
  SeriesPlot plot = twoSeriesPlot();
  plot.log_x = plot.log_y = true;
  plot.front = true;
  plot.series[0].points.push_back({0, 1, "zero"});
  plot.series[1].points.push_back({100, kNaN, "nan"});
  const std::string svg = seriesChart(plot);
  expectWellFormedChart(svg);
  // (30, 2) beats every other point in both coordinates: the front is that one point, ringed.
  EXPECT_EQ(countOccurrences(svg, "<circle "), 5 + 1);
  EXPECT_NE(svg.find("points without a drawable value not shown: 2"), std::string::npos);
  EXPECT_NE(svg.find(">Pareto front<"), std::string::npos);
  EXPECT_NE(svg.find(">1000<"), std::string::npos);  // x decades

  plot.series = {};
  const std::string empty = seriesChart(plot);
  expectWellFormedChart(empty);
  EXPECT_NE(empty.find("no point with values the axes can show"), std::string::npos);
}

}  // namespace
}  // namespace gib::reports
