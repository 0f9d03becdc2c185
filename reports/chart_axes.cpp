#include "reports/chart_axes.h"

#include "reports/number_format.h"

#include <algorithm>
#include <cmath>

namespace gib::reports {

namespace {

// Tick labels get more digits than table values: a step of 0.25 on an axis at 1000 must show as
// 1000.25, and six digits hide the rounding of k · step.
constexpr int kTickDigits = 6;
// At most this many labelled decades; more get a stride of 2, 3, …
constexpr int kMaxDecadeLabels = 7;

// The smallest of 1, 2, 5 × 10^k not below `raw`.
double niceStep(double raw) {
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (double factor : {1.0, 2.0, 5.0, 10.0})
    if (factor * magnitude >= raw * (1 - 1e-12)) return factor * magnitude;
  return 10.0 * magnitude;
}

}  // namespace

Axis linearAxis(double low, double high, int target) {
  if (low > high) std::swap(low, high);
  if (low == high) {
    // One value: a range around it of half its size (or unit size around zero).
    const double pad = low == 0 ? 1.0 : 0.5 * std::abs(low);
    low -= pad;
    high += pad;
  }
  const double step = niceStep((high - low) / std::max(1, target));
  const double first = std::floor(low / step), last = std::ceil(high / step);
  Axis axis;
  axis.low = first * step;
  axis.high = last * step;
  for (double k = first; k <= last; ++k) {
    const double value = k == 0 ? 0.0 : k * step;  // computed, not accumulated: no drift
    axis.ticks.push_back({value, formatNumber(value, kTickDigits)});
  }
  return axis;
}

Axis logAxis(double low, double high) {
  if (low > high) std::swap(low, high);
  const int first = int(std::floor(std::log10(low)));
  int last = int(std::ceil(std::log10(high)));
  if (last == first) ++last;
  Axis axis;
  axis.log = true;
  axis.low = std::pow(10.0, first);
  axis.high = std::pow(10.0, last);
  const int decades = last - first;
  const int stride = (decades + kMaxDecadeLabels - 1) / kMaxDecadeLabels;
  for (int k = first; k <= last; ++k)
    if ((k - first) % stride == 0)
      axis.ticks.push_back({std::pow(10.0, k), formatNumber(std::pow(10.0, k), kTickDigits)});
  for (int k = first; k < last; ++k)
    for (int m = 2; m <= 9; ++m) axis.ticks.push_back({m * std::pow(10.0, k), ""});
  return axis;
}

double axisPixel(const Axis& axis, double value, double from, double to) {
  const double t = axis.log ? (std::log10(value) - std::log10(axis.low)) /
                                  (std::log10(axis.high) - std::log10(axis.low))
                            : (value - axis.low) / (axis.high - axis.low);
  return from + t * (to - from);
}

}  // namespace gib::reports
