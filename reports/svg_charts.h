// The report's charts as inline SVG strings: pure functions of their data, with escaped text, a
// viewBox, no fonts or scripts from outside. Values that cannot be drawn (non-finite; zero or
// negative on a log axis) are left out and counted in a note on the chart, so a chart never
// carries "nan" and never hides that something was dropped.
#pragma once

#include "reports/number_format.h"

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gib::reports {

// One row of the per-pass timing table (metrics::PassTimings): the frame at depth 0, its
// passes below it.
struct PassBar {
  std::string name;
  int depth = 0;
  double median_ms = 0, first_quartile_ms = 0, third_quartile_ms = 0;
};

// Horizontal bars of the median time per pass with whiskers from the first to the third
// quartile, one row per pass in the given (depth-first) order, names indented by depth. `unit`
// is what one sample times ("frame", "iteration"); the times are drawn and labelled in `time`
// (the pass table's unit, µs for a sub-millisecond frame).
std::string passTimingChart(const std::vector<PassBar>& passes, std::string_view unit = "frame",
                            const TimeUnit& time = {"ms", 1.0});

// Per-sample times of each pass as a strip plot: one dot per sample (frame, iteration) on a
// shared time axis, a row per pass with its name indented by depth and its median marked, so
// that outliers and a bimodal spread show where a median and quartiles hide them.
struct StripRow {
  std::string name;
  int depth = 0;
  std::vector<double> values;  // in the plot's unit
};
struct StripPlot {
  std::string title;
  std::string sample;  // what one dot is: "frame", "iteration"
  std::string unit;    // of the values: "ms", "µs"
  std::vector<StripRow> rows;
};
std::string stripChart(const StripPlot& plot);

struct FittedSlope {
  double slope = 0;
  double ci95 = 0;  // half-width of the 95% interval; infinite (with two points) is not shown
};

// Points on log-log axes, and when `fit` is given, the least-squares line with that slope
// through the centroid of the drawn points in log space (where every least-squares line passes,
// so no intercept convention is needed) with a label naming what was fitted, the y quantity:
// "relmse: slope −0.98 ± 0.03".
struct LogLogPlot {
  std::string title;
  std::string x_label, y_label;
  std::vector<std::pair<double, double>> points;  // (x, y)
  std::optional<FittedSlope> fit;
};
std::string logLogChart(const LogLogPlot& plot);

// Figure charts of a suite ([[chart]]): points of several series on linear or log axes, each
// series joined in x order, with a legend; with `front`, the Pareto front over all series (the
// points no other point beats in both x and y, e.g. error against frame time) drawn as a
// highlighted step line.
struct ChartPoint {
  double x = 0, y = 0;
  std::string label;  // the job, for the tooltip
};
struct ChartSeries {
  std::string name;  // empty for a single unnamed series
  std::vector<ChartPoint> points;
};
struct SeriesPlot {
  std::string title;
  std::string x_label, y_label;
  bool log_x = false, log_y = false;
  bool front = false;
  std::vector<ChartSeries> series;
};
std::string seriesChart(const SeriesPlot& plot);

// Indices (into `points`) of the Pareto front minimising both x and y, in increasing x.
std::vector<std::size_t> paretoFront(const std::vector<std::pair<double, double>>& points);

// A value over runs, oldest first: x is the run index, labelled with `label` (a short commit);
// the last point (this run) is highlighted.
struct TrendPoint {
  std::string label;
  double value = 0;
};
std::string trendChart(std::string_view title, std::string_view y_label,
                       const std::vector<TrendPoint>& runs);

// The colour bar of the FLIP map: the magma map of image/false_color.h (the FLIP PNGs' map) from
// 0 to 1, labelled.
std::string flipColorBar();

}  // namespace gib::reports
