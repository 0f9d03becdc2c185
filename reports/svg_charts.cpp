#include "reports/svg_charts.h"

#include "image/false_color.h"
#include "metrics/timing_statistics.h"
#include "reports/chart_axes.h"
#include "reports/number_format.h"
#include "reports/svg_writer.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace gib::reports {

namespace {

constexpr const char* kAxisStroke = R"(stroke="#555" stroke-width="1")";
constexpr const char* kGridStroke = R"(stroke="#e2e2e2" stroke-width="1")";
constexpr const char* kDataColor = "#2f5f98";
constexpr const char* kHighlightColor = "#c0392b";
// Average advance of a character of the 11 px sans-serif the charts use, for sizing label
// columns without measuring text (a browser-independent estimate, generous on purpose).
constexpr double kCharWidth = 6.5;

struct PlotArea {
  double left, top, right, bottom;
};

bool drawable(double value) {
  return std::isfinite(value);
}
bool drawableOnLog(double value) {
  return std::isfinite(value) && value > 0;
}

void drawXAxis(SvgWriter& svg, const PlotArea& area, const Axis& axis, std::string_view title) {
  svg.line(area.left, area.bottom, area.right, area.bottom, kAxisStroke);
  for (const Tick& tick : axis.ticks) {
    const double x = axisPixel(axis, tick.value, area.left, area.right);
    const bool major = !tick.label.empty();
    if (major) svg.line(x, area.top, x, area.bottom, kGridStroke);
    svg.line(x, area.bottom, x, area.bottom + (major ? 5 : 3), kAxisStroke);
    if (major) svg.text(x, area.bottom + 16, tick.label, "middle");
  }
  svg.text((area.left + area.right) / 2, area.bottom + 32, title, "middle");
}

void drawYAxis(SvgWriter& svg, const PlotArea& area, const Axis& axis, std::string_view title) {
  svg.line(area.left, area.top, area.left, area.bottom, kAxisStroke);
  for (const Tick& tick : axis.ticks) {
    const double y = axisPixel(axis, tick.value, area.bottom, area.top);
    const bool major = !tick.label.empty();
    if (major) svg.line(area.left, y, area.right, y, kGridStroke);
    svg.line(area.left - (major ? 5 : 3), y, area.left, y, kAxisStroke);
    if (major) svg.text(area.left - 8, y + 4, tick.label, "end");
  }
  svg.text(14, (area.top + area.bottom) / 2, title, "middle", {}, -90);
}

void drawTitle(SvgWriter& svg, const PlotArea& area, std::string_view title) {
  svg.text(area.left, 16, title, "start", R"(font-weight="bold")");
}

// "runs without a finite value not shown: 2": the reader learns that the chart is not the whole
// data.
void drawSkippedNote(SvgWriter& svg, double x, double y, int skipped, std::string_view what) {
  if (skipped == 0) return;
  svg.text(x, y, fmt::format("{} not shown: {}", what, skipped), "start",
           R"(fill="#a33" font-style="italic")");
}

struct Bounds {
  double x_low, x_high, y_low, y_high;
};

// The smallest box around the points; `empty` when there are none.
Bounds pointBounds(const std::vector<std::pair<double, double>>& points, Bounds empty) {
  if (points.empty()) return empty;
  auto [xl, xh] = std::minmax_element(points.begin(), points.end());
  auto [yl, yh] = std::minmax_element(points.begin(), points.end(),
                                      [](auto& a, auto& b) { return a.second < b.second; });
  return {xl->first, xh->first, yl->second, yh->second};
}

std::string fill(std::string_view color) {
  return fmt::format(R"(fill="{}")", color);
}

// "relmse: slope −0.98 ± 0.03" (`fitted`: the y quantity): the slope with as many decimals as its
// interval's first digit needs.
std::string slopeLabel(std::string_view fitted, const FittedSlope& fit) {
  const std::string prefix = fitted.empty() ? std::string() : fmt::format("{}: ", fitted);
  if (!std::isfinite(fit.ci95))
    return prefix + "slope " + withMinusSign(formatNumber(fit.slope, 3));
  const int decimals = fit.ci95 > 0 ? std::clamp(int(-std::floor(std::log10(fit.ci95))), 2, 6) : 2;
  return prefix + fmt::format("slope {} \u00b1 {:.{}f}",
                              withMinusSign(fmt::format("{:.{}f}", fit.slope, decimals)), fit.ci95,
                              decimals);
}

std::string hexColor(const float rgb[3]) {
  auto byte = [](float v) { return int(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  return fmt::format("#{:02x}{:02x}{:02x}", byte(rgb[0]), byte(rgb[1]), byte(rgb[2]));
}

}  // namespace

std::string passTimingChart(const std::vector<PassBar>& passes_ms, std::string_view unit,
                            const TimeUnit& time) {
  constexpr double kRowHeight = 20, kIndent = 12, kTop = 8, kBarsWidth = 360, kValueWidth = 84;
  constexpr std::array<const char*, 3> kDepthColors = {"#2f5f98", "#5b8bc6", "#93b5de"};
  // From here on the bars' times are in `time`'s unit.
  std::vector<PassBar> passes = passes_ms;
  for (PassBar& pass : passes)
    for (double* value : {&pass.median_ms, &pass.first_quartile_ms, &pass.third_quartile_ms})
      *value *= time.per_ms;
  const std::string symbol = time.symbol;
  std::vector<const PassBar*> drawn;
  double label_width = 80, top_value = 0;
  for (const PassBar& pass : passes) {
    if (!drawable(pass.median_ms) || pass.median_ms < 0) continue;
    drawn.push_back(&pass);
    label_width = std::max(label_width, 16 + kIndent * pass.depth + kCharWidth * pass.name.size());
    top_value = std::max({top_value, pass.median_ms,
                          drawable(pass.third_quartile_ms) ? pass.third_quartile_ms : 0.0});
  }
  const int skipped = int(passes.size() - drawn.size());
  const PlotArea area{label_width, kTop, label_width + kBarsWidth,
                      kTop + kRowHeight * double(std::max<std::size_t>(1, drawn.size()))};
  const double height = area.bottom + 40 + (skipped ? 16 : 0);
  SvgWriter svg(area.right + kValueWidth, height, "Median time per pass in " + symbol);
  const Axis axis = linearAxis(0, top_value > 0 ? top_value : 1);
  drawXAxis(svg, area, axis,
            fmt::format("{} per {}: median, whiskers from first to third quartile", symbol, unit));
  if (drawn.empty()) svg.text(area.left + 8, kTop + 14, "no finite pass times");
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    const PassBar& pass = *drawn[i];
    const double y = kTop + kRowHeight * double(i);
    const double end = axisPixel(axis, pass.median_ms, area.left, area.right);
    const bool whisker = drawable(pass.first_quartile_ms) && drawable(pass.third_quartile_ms) &&
                         pass.first_quartile_ms >= 0 &&
                         pass.first_quartile_ms <= pass.third_quartile_ms;
    std::string tooltip =
        fmt::format("{}: median {} {}", pass.name, formatNumber(pass.median_ms), symbol);
    if (whisker)
      tooltip += fmt::format(", quartiles {} to {} {}", formatNumber(pass.first_quartile_ms),
                             formatNumber(pass.third_quartile_ms), symbol);
    svg.text(8 + kIndent * pass.depth, y + 14, pass.name);
    svg.rect(area.left, y + 4, end - area.left, 12,
             fill(kDepthColors[std::min<std::size_t>(std::size_t(std::max(0, pass.depth)),
                                                     kDepthColors.size() - 1)]),
             tooltip);
    if (whisker) {
      const double q1 = axisPixel(axis, pass.first_quartile_ms, area.left, area.right);
      const double q3 = axisPixel(axis, pass.third_quartile_ms, area.left, area.right);
      const double mid = y + 10;
      svg.path(SvgWriter::moveTo(q1, mid) + SvgWriter::horizontalTo(q3) +
                   SvgWriter::moveTo(q1, mid - 4) + SvgWriter::verticalTo(mid + 4) +
                   SvgWriter::moveTo(q3, mid - 4) + SvgWriter::verticalTo(mid + 4),
               R"(stroke="#222" stroke-width="1" fill="none")");
    }
    svg.text(area.right + 6, y + 14, formatNumber(pass.median_ms) + " " + symbol);
  }
  drawSkippedNote(svg, 8, height - 6, skipped, "passes without a finite time");
  return svg.finish();
}

std::string stripChart(const StripPlot& plot) {
  constexpr double kRowHeight = 20, kIndent = 12, kTop = 28, kPlotWidth = 360, kJitter = 4;
  double label_width = 80, top_value = 0;
  int skipped = 0;
  for (const StripRow& row : plot.rows) {
    label_width = std::max(label_width, 16 + kIndent * row.depth + kCharWidth * row.name.size());
    for (double value : row.values) {
      if (drawable(value))
        top_value = std::max(top_value, value);
      else
        ++skipped;
    }
  }
  const PlotArea area{label_width, kTop, label_width + kPlotWidth,
                      kTop + kRowHeight * double(std::max<std::size_t>(1, plot.rows.size()))};
  const double height = area.bottom + 40 + (skipped ? 16 : 0);
  SvgWriter svg(area.right + 16, height, plot.title);
  drawTitle(svg, area, plot.title);
  const Axis axis = linearAxis(0, top_value > 0 ? top_value : 1);
  drawXAxis(svg, area, axis,
            fmt::format("{} per {}: a dot per {}, the bar at the median", plot.unit, plot.sample,
                        plot.sample));
  const std::string dot = fmt::format(R"(fill="{}" fill-opacity="0.55")", kDataColor);
  for (std::size_t r = 0; r < plot.rows.size(); ++r) {
    const StripRow& row = plot.rows[r];
    const double mid = kTop + kRowHeight * (double(r) + 0.5);
    svg.text(8 + kIndent * row.depth, mid + 4, row.name);
    std::vector<double> finite;
    for (std::size_t i = 0; i < row.values.size(); ++i) {
      const double value = row.values[i];
      if (!drawable(value)) continue;
      finite.push_back(value);
      // A fixed vertical spread by sample index, so that equal times stay apart and a run's
      // picture does not change between reports.
      const double jitter = kJitter * (double(i * 7 % 9) / 4.0 - 1.0);
      svg.circle(axisPixel(axis, value, area.left, area.right), mid + jitter, 2.5, dot,
                 fmt::format("{} {}, {}: {} {}", plot.sample, i + 1, row.name, formatNumber(value),
                             plot.unit));
    }
    if (finite.empty()) continue;
    // The table's median (the same interpolating quantile), so the bar and the number agree.
    const double median = axisPixel(axis, metrics::quantile(finite, 0.5), area.left, area.right);
    svg.line(median, mid - 8, median, mid + 8,
             fmt::format(R"(stroke="{}" stroke-width="2")", kHighlightColor));
  }
  drawSkippedNote(svg, 8, height - 6, skipped, "samples without a finite time");
  return svg.finish();
}

std::string logLogChart(const LogLogPlot& plot) {
  constexpr double kWidth = 480, kHeight = 330;
  const PlotArea area{70, 28, kWidth - 16, kHeight - 62};
  std::vector<std::pair<double, double>> drawn;
  for (const auto& [x, y] : plot.points)
    if (drawableOnLog(x) && drawableOnLog(y)) drawn.emplace_back(x, y);
  const int skipped = int(plot.points.size() - drawn.size());

  // Value ranges of the points and of the fitted line's ends.
  auto [x_low, x_high, y_low, y_high] = pointBounds(drawn, {1, 10, 1, 10});
  std::optional<std::array<double, 4>> line;  // x0, y0, x1, y1
  if (plot.fit && drawn.size() >= 2 && std::isfinite(plot.fit->slope) && x_low < x_high) {
    double cx = 0, cy = 0;
    for (const auto& [x, y] : drawn) {
      cx += std::log10(x) / double(drawn.size());
      cy += std::log10(y) / double(drawn.size());
    }
    auto at = [&](double x) { return std::pow(10.0, cy + plot.fit->slope * (std::log10(x) - cx)); };
    const double y0 = at(x_low), y1 = at(x_high);
    if (drawableOnLog(y0) && drawableOnLog(y1)) {
      line = std::array<double, 4>{x_low, y0, x_high, y1};
      y_low = std::min({y_low, y0, y1});
      y_high = std::max({y_high, y0, y1});
    }
  }
  const Axis x_axis = logAxis(x_low, x_high), y_axis = logAxis(y_low, y_high);
  auto px = [&](double x) { return axisPixel(x_axis, x, area.left, area.right); };
  auto py = [&](double y) { return axisPixel(y_axis, y, area.bottom, area.top); };

  SvgWriter svg(kWidth, kHeight, plot.title);
  drawTitle(svg, area, plot.title);
  drawXAxis(svg, area, x_axis, plot.x_label);
  drawYAxis(svg, area, y_axis, plot.y_label);
  if (line) {
    const auto& [x0, y0, x1, y1] = *line;
    svg.line(
        px(x0), py(y0), px(x1), py(y1),
        fmt::format(R"(stroke="{}" stroke-width="1.5" stroke-dasharray="6 3")", kHighlightColor));
  }
  for (const auto& [x, y] : drawn)
    svg.circle(
        px(x), py(y), 3.5, fill(kDataColor),
        fmt::format("{} {}: {} {}", plot.x_label, formatNumber(x), plot.y_label, formatNumber(y)));
  if (line)
    svg.text(area.right - 6, area.top + 16, slopeLabel(plot.y_label, *plot.fit), "end",
             fmt::format(R"(fill="{}" font-weight="bold")", kHighlightColor));
  if (drawn.empty()) svg.text(area.left + 8, area.top + 16, "no point with positive values");
  drawSkippedNote(svg, 8, kHeight - 6, skipped, "points with zero or non-finite values");
  return svg.finish();
}

std::vector<std::size_t> paretoFront(const std::vector<std::pair<double, double>>& points) {
  std::vector<std::size_t> order(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return points[a] < points[b];  // by x, then y
  });
  // Walking in increasing x, a point is on the front when its y is below every y seen so far.
  std::vector<std::size_t> front;
  double best_y = std::numeric_limits<double>::infinity();
  for (std::size_t i : order)
    if (points[i].second < best_y) {
      best_y = points[i].second;
      front.push_back(i);
    }
  return front;
}

std::string seriesChart(const SeriesPlot& plot) {
  constexpr std::array<const char*, 8> kSeriesColors = {"#2f5f98", "#e08a1e", "#3a9a5b", "#8e44ad",
                                                        "#c0392b", "#16a5a5", "#7f6a00", "#555555"};
  auto ok_x = [&](double v) { return plot.log_x ? drawableOnLog(v) : drawable(v); };
  auto ok_y = [&](double v) { return plot.log_y ? drawableOnLog(v) : drawable(v); };

  std::vector<std::vector<ChartPoint>> drawn(plot.series.size());
  std::vector<std::pair<double, double>> all;
  int skipped = 0;
  for (std::size_t s = 0; s < plot.series.size(); ++s) {
    for (const ChartPoint& p : plot.series[s].points) {
      if (!ok_x(p.x) || !ok_y(p.y)) {
        ++skipped;
        continue;
      }
      drawn[s].push_back(p);
      all.emplace_back(p.x, p.y);
    }
    std::sort(drawn[s].begin(), drawn[s].end(),
              [](const ChartPoint& a, const ChartPoint& b) { return a.x < b.x; });
  }

  auto [x_low, x_high, y_low, y_high] =
      pointBounds(all, {plot.log_x ? 1.0 : 0.0, plot.log_x ? 10.0 : 1.0, plot.log_y ? 1.0 : 0.0,
                        plot.log_y ? 10.0 : 1.0});
  // Linear axes start at zero when the data are all positive, so bars of time read true.
  if (!plot.log_y && y_low > 0) y_low = 0;
  const Axis x_axis = plot.log_x ? logAxis(x_low, x_high) : linearAxis(x_low, x_high);
  const Axis y_axis = plot.log_y ? logAxis(y_low, y_high) : linearAxis(y_low, y_high);

  double legend_width = 0;
  for (const ChartSeries& series : plot.series)
    if (!series.name.empty())
      legend_width = std::max(legend_width, 28 + kCharWidth * double(series.name.size()));
  if (plot.front) legend_width = std::max(legend_width, 28 + kCharWidth * 12);
  constexpr double kWidth = 520, kHeight = 340;
  const PlotArea area{70, 28, kWidth - 16, kHeight - 62};
  SvgWriter svg(kWidth + legend_width, kHeight, plot.title);
  drawTitle(svg, area, plot.title);
  drawXAxis(svg, area, x_axis, plot.x_label);
  drawYAxis(svg, area, y_axis, plot.y_label);
  auto px = [&](double x) { return axisPixel(x_axis, x, area.left, area.right); };
  auto py = [&](double y) { return axisPixel(y_axis, y, area.bottom, area.top); };

  for (std::size_t s = 0; s < drawn.size(); ++s) {
    const char* color = kSeriesColors[s % kSeriesColors.size()];
    if (drawn[s].size() >= 2) {
      std::vector<std::pair<double, double>> line;
      for (const ChartPoint& p : drawn[s]) line.emplace_back(px(p.x), py(p.y));
      // polyline() writes fill="none" itself: an attribute given twice is not XML, and the
      // chart is also written as a standalone .svg file (reports/figure_charts.h).
      svg.polyline(line, fmt::format(R"(stroke="{}" stroke-width="1.5")", color));
    }
    for (const ChartPoint& p : drawn[s]) {
      std::string tooltip = fmt::format("{}: {} {}, {} {}", p.label, plot.x_label,
                                        formatNumber(p.x), plot.y_label, formatNumber(p.y));
      if (!plot.series[s].name.empty()) tooltip = plot.series[s].name + " — " + tooltip;
      svg.circle(px(p.x), py(p.y), 3.5, fill(color), tooltip);
    }
  }
  if (plot.front && all.size() >= 2) {
    std::string data;
    const std::vector<std::size_t> front = paretoFront(all);
    for (std::size_t i = 0; i < front.size(); ++i) {
      const auto& [x, y] = all[front[i]];
      data += i == 0 ? SvgWriter::moveTo(px(x), py(y))
                     : SvgWriter::horizontalTo(px(x)) + SvgWriter::verticalTo(py(y));
    }
    svg.path(data, fmt::format(R"(stroke="{}" stroke-width="2" stroke-dasharray="5 3" fill="none")",
                               kHighlightColor));
    for (std::size_t i : front)
      svg.circle(px(all[i].first), py(all[i].second), 6,
                 fmt::format(R"(fill="none" stroke="{}" stroke-width="1.5")", kHighlightColor));
  }

  // Legend to the right of the plot.
  double legend_y = area.top + 4;
  for (std::size_t s = 0; s < plot.series.size(); ++s) {
    if (plot.series[s].name.empty()) continue;
    svg.rect(kWidth, legend_y, 12, 12, fill(kSeriesColors[s % kSeriesColors.size()]));
    svg.text(kWidth + 18, legend_y + 10, plot.series[s].name);
    legend_y += 18;
  }
  if (plot.front) {
    svg.line(
        kWidth, legend_y + 6, kWidth + 12, legend_y + 6,
        fmt::format(R"(stroke="{}" stroke-width="2" stroke-dasharray="5 3")", kHighlightColor));
    svg.text(kWidth + 18, legend_y + 10, "Pareto front");
  }
  if (all.empty())
    svg.text(area.left + 8, area.top + 16,
             plot.log_x || plot.log_y ? "no point with values the axes can show"
                                      : "no point with finite values");
  drawSkippedNote(svg, 8, kHeight - 6, skipped, "points without a drawable value");
  return svg.finish();
}

std::string trendChart(std::string_view title, std::string_view y_label,
                       const std::vector<TrendPoint>& runs) {
  constexpr double kRunSpacing = 48, kMinPlotWidth = 240;
  const double n = double(std::max<std::size_t>(1, runs.size()));
  const PlotArea area{70, 28, 70 + std::max(kMinPlotWidth, kRunSpacing * n), 190};
  // Below the axis: commit labels rotated by 40° (about 50 px), the axis title, the note.
  const double width = area.right + 24;
  auto run_x = [&](std::size_t i) {
    return area.left + (double(i) + 0.5) * (area.right - area.left) / n;
  };
  std::vector<std::size_t> drawn;  // indices of runs with a finite value
  for (std::size_t i = 0; i < runs.size(); ++i)
    if (drawable(runs[i].value)) drawn.push_back(i);
  const int skipped = int(runs.size() - drawn.size());
  const double height = area.bottom + 80 + (skipped ? 16 : 0);
  double low = 0, high = 1;
  if (!drawn.empty()) {
    auto [l, h] = std::minmax_element(
        drawn.begin(), drawn.end(), [&](auto a, auto b) { return runs[a].value < runs[b].value; });
    low = runs[*l].value;
    high = runs[*h].value;
  }
  const Axis axis = linearAxis(low, high);
  auto py = [&](std::size_t i) { return axisPixel(axis, runs[i].value, area.bottom, area.top); };

  SvgWriter svg(width, height, title);
  drawTitle(svg, area, title);
  drawYAxis(svg, area, axis, y_label);
  svg.line(area.left, area.bottom, area.right, area.bottom, kAxisStroke);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    svg.line(run_x(i), area.bottom, run_x(i), area.bottom + 4, kAxisStroke);
    svg.text(run_x(i), area.bottom + 14, runs[i].label, "end", {}, -40);
  }
  svg.text((area.left + area.right) / 2, area.bottom + 72, "run (oldest first), commit", "middle");
  if (drawn.size() >= 2) {
    std::vector<std::pair<double, double>> pixels;
    for (std::size_t i : drawn) pixels.emplace_back(run_x(i), py(i));
    svg.polyline(pixels, fmt::format(R"(stroke="{}" stroke-width="1.5")", kDataColor));
  }
  for (std::size_t i : drawn) {
    const bool current = i + 1 == runs.size();  // the newest run is the one reported
    svg.circle(run_x(i), py(i), current ? 5 : 3.5, fill(current ? kHighlightColor : kDataColor),
               fmt::format("{}{}: {}", current ? "this run, " : "", runs[i].label,
                           formatNumber(runs[i].value)));
  }
  if (drawn.empty()) svg.text(area.left + 8, area.top + 16, "no finite values");
  drawSkippedNote(svg, 8, height - 6, skipped, "runs without a finite value");
  return svg.finish();
}

std::string flipColorBar() {
  constexpr double kWidth = 320, kHeight = 56, kLeft = 12, kRight = kWidth - 12, kTop = 22;
  constexpr int kStops = 9;  // the samples magmaSrgb interpolates between: the gradient is exact
  std::string gradient =
      R"(<defs><linearGradient id="gib-flip-magma" x1="0" x2="1" y1="0" y2="0">)";
  for (int i = 0; i < kStops; ++i) {
    const float t = float(i) / float(kStops - 1);
    float rgb[3];
    image::magmaSrgb(t, rgb);
    gradient +=
        fmt::format(R"(<stop offset="{}" stop-color="{}"/>)", formatNumber(t), hexColor(rgb));
  }
  gradient += "</linearGradient></defs>";
  SvgWriter svg(kWidth, kHeight, "FLIP error colour bar, 0 to 1");
  svg.raw(gradient);
  svg.text(kLeft, 14, "FLIP error (0: no visible difference, 1: maximal)");
  svg.rect(kLeft, kTop, kRight - kLeft, 14, R"svg(fill="url(#gib-flip-magma)" stroke="#555")svg");
  for (double value : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const double x = kLeft + value * (kRight - kLeft);
    svg.line(x, kTop + 14, x, kTop + 19, kAxisStroke);
    svg.text(x, kTop + 31, formatNumber(value), "middle");
  }
  return svg.finish();
}

}  // namespace gib::reports
