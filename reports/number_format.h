// Numbers for people in the report and its charts: a few significant digits, plain decimals in
// the everyday range and short scientific notation outside it ("0.0123", "197.3", "1.2e-5").
#pragma once

#include <string>

namespace gib::reports {

// `significant` digits, trailing zeros dropped ("0.5", not "0.5000"); "NaN", "inf" or "-inf" for
// non-finite values (the charts never pass those: they skip them with a note).
std::string formatNumber(double value, int significant = 4);

// A relative change as a signed percentage with one decimal: "+12.5%", "-3.0%".
std::string formatChange(double relative);

// A share of a whole (0.25) as "25.0%".
std::string formatShare(double fraction);

// A unit for times in milliseconds: microseconds below a millisecond (52 µs reads better than
// 0.052 ms), else milliseconds. `per_ms`: how many of the unit make a millisecond.
struct TimeUnit {
  const char* symbol;  // "ms", "µs"
  double per_ms;
};
TimeUnit timeUnitFor(double largest_ms);

// A duration in milliseconds with the unit that reads best: "436 ms", "52 µs"; formatNumber's
// text (no unit) for a non-finite value.
std::string formatMilliseconds(double ms);

// The text with a leading '-' turned into the typographic minus sign (U+2212) for labels.
std::string withMinusSign(std::string text);

}  // namespace gib::reports
