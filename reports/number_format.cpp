#include "reports/number_format.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace gib::reports {

namespace {

// Plain decimals between these magnitudes; scientific notation outside.
constexpr double kSmallestPlain = 1e-3;
constexpr double kLargestPlain = 1e6;

void dropTrailingZeros(std::string& digits) {
  if (digits.find('.') == std::string::npos) return;
  while (digits.back() == '0') digits.pop_back();
  if (digits.back() == '.') digits.pop_back();
}

// "1.2300e-05" → "1.23e-5".
std::string shortScientific(double value, int significant) {
  std::string text = fmt::format("{:.{}e}", value, std::max(0, significant - 1));
  const std::size_t e = text.find('e');
  std::string mantissa = text.substr(0, e);
  dropTrailingZeros(mantissa);
  const int exponent = std::stoi(text.substr(e + 1));
  return fmt::format("{}e{}", mantissa, exponent);
}

}  // namespace

std::string formatNumber(double value, int significant) {
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (value == 0) return "0";
  significant = std::max(1, significant);
  const double magnitude = std::abs(value);
  if (magnitude < kSmallestPlain || magnitude >= kLargestPlain)
    return shortScientific(value, significant);
  const int leading = int(std::floor(std::log10(magnitude)));
  std::string text = fmt::format("{:.{}f}", value, std::max(0, significant - 1 - leading));
  dropTrailingZeros(text);
  return text == "-0" ? "0" : text;
}

std::string formatChange(double relative) {
  if (!std::isfinite(relative)) return formatNumber(relative);
  return fmt::format("{:+.1f}%", 100.0 * relative);
}

std::string formatShare(double fraction) {
  if (!std::isfinite(fraction)) return formatNumber(fraction);
  return fmt::format("{:.1f}%", 100.0 * fraction);
}

TimeUnit timeUnitFor(double largest_ms) {
  if (std::isfinite(largest_ms) && std::abs(largest_ms) < 1.0) return {"\u00b5s", 1000.0};
  return {"ms", 1.0};
}

std::string formatMilliseconds(double ms) {
  if (!std::isfinite(ms)) return formatNumber(ms);
  const TimeUnit unit = timeUnitFor(ms == 0 ? 1.0 : ms);  // "0 ms", not "0 µs"
  return fmt::format("{} {}", formatNumber(ms * unit.per_ms), unit.symbol);
}

std::string withMinusSign(std::string text) {
  if (!text.empty() && text.front() == '-') text.replace(0, 1, "\u2212");
  return text;
}

}  // namespace gib::reports
