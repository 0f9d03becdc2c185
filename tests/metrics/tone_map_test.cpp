#include "metrics/tone_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace gib::metrics {
namespace {

TEST(ToneMap, TableMatchesTheExactSrgbCurve) {
  // About 90 000 values spread geometrically over [1e-4, 1], then the clamps and NaN.
  float worst = 0;
  for (float v = 1e-4f; v < 1.0f; v = std::nextafter(v, 2.0f) + v * 1e-4f)
    worst = std::max(worst, std::abs(displayEncode(v) - displayEncodeExact(v)));
  EXPECT_LT(worst, 2e-7f);
  EXPECT_EQ(displayEncode(-1.0f), 0.0f);
  EXPECT_EQ(displayEncode(5.0f), 1.0f);
  EXPECT_EQ(displayEncode(1.0f), 1.0f);
  EXPECT_NEAR(displayEncode(0.18f), 0.4613561f, 1e-6f);  // 0.18 → 118/255 in 8 bits
  EXPECT_EQ(displayEncode(std::numeric_limits<float>::quiet_NaN()), 0.0f);
}

}  // namespace
}  // namespace gib::metrics
