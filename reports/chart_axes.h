// Axes of the report's charts: value ranges widened to round numbers, tick values with labels,
// and the mapping from values to pixels. Linear axes tick at 1, 2 or 5 × 10^k; log axes at whole
// decades, the way a reader of a convergence plot expects (0.001, 0.01, 0.1, 1, 10, 1e4).
#pragma once

#include <string>
#include <vector>

namespace gib::reports {

struct Tick {
  double value = 0;
  std::string label;  // empty for a minor tick (log axes: 2..9 × 10^k)
};

struct Axis {
  double low = 0, high = 1;  // the range the axis spans, low < high, both finite
  bool log = false;
  std::vector<Tick> ticks;  // labelled ticks first, in increasing order; then minor ticks
};

// About `target` labelled ticks over [low, high], widened to multiples of the tick step. A
// degenerate range (low == high) is widened around its value; arguments must be finite.
Axis linearAxis(double low, double high, int target = 5);

// Whole decades covering [low, high] (both finite and > 0; at least one decade), a labelled tick
// at each decade (every second or third when there are many) and minor ticks at 2..9 × 10^k.
Axis logAxis(double low, double high);

// The pixel position of `value` on an axis drawn from pixel `from` (at axis.low) to `to` (at
// axis.high). Values outside the range map outside [from, to].
double axisPixel(const Axis& axis, double value, double from, double to);

}  // namespace gib::reports
