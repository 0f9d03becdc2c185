#include "metrics/tone_map.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

namespace gib::metrics {

namespace {

constexpr float kToeEnd = 0.0031308f;  // below: the linear segment 12.92·x
constexpr int kMantissaBits = 10;      // 1024 intervals per octave
constexpr int kFirstExponent = -9;     // 2^-9 < kToeEnd: every power-segment input is covered
constexpr int kOctaves = 9;            // up to 2^0 = 1
constexpr int kEntries = kOctaves << kMantissaBits;

double encodePower(double v) {
  return 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

// Table of the curve at the left end of each interval, plus one entry for 1.0.
const std::array<float, kEntries + 1>& table() {
  static const auto t = [] {
    std::array<float, kEntries + 1> values{};
    for (int i = 0; i <= kEntries; ++i) {
      const int octave = i >> kMantissaBits;
      const double fraction = double(i & ((1 << kMantissaBits) - 1)) / double(1 << kMantissaBits);
      values[std::size_t(i)] =
          float(encodePower(std::ldexp(1.0 + fraction, kFirstExponent + octave)));
    }
    return values;
  }();
  return t;
}

}  // namespace

float displayEncode(float linear) {
  const float v = std::clamp(linear, 0.0f, 1.0f);
  if (!(v > kToeEnd)) return 12.92f * (std::isnan(v) ? 0.0f : v);
  if (v >= 1.0f) return 1.0f;
  // The float's bits: exponent and the top mantissa bits give the interval, the rest the
  // position inside it.
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(v);
  const int exponent = int(bits >> 23) - 127;
  const std::uint32_t mantissa = bits & 0x7fffffu;
  const int index =
      ((exponent - kFirstExponent) << kMantissaBits) | int(mantissa >> (23 - kMantissaBits));
  const float t = float(mantissa & ((1u << (23 - kMantissaBits)) - 1)) *
                  (1.0f / float(1u << (23 - kMantissaBits)));
  const auto& values = table();
  return values[std::size_t(index)] +
         t * (values[std::size_t(index) + 1] - values[std::size_t(index)]);
}

float displayEncodeExact(float linear) {
  const float v = std::clamp(linear, 0.0f, 1.0f);
  return v <= kToeEnd ? 12.92f * v : float(encodePower(v));
}

}  // namespace gib::metrics
