#include "image/false_color.h"

#include "common/luminance_shared.h"

#include <gtest/gtest.h>

namespace gib::image {
namespace {

TEST(FalseColor, MapsTheRangeOntoMagmaAndAddsALabelledBar) {
  Image scalar(200, 100, 1, 0.0f);
  for (int x = 100; x < 200; ++x)
    for (int y = 0; y < 100; ++y) scalar.pixel(x, y)[0] = 2.0f;
  Image out = falseColorWithBar(scalar, 0.0f, 2.0f);
  EXPECT_EQ(out.width(), 200);
  EXPECT_GT(out.height(), 100);
  // Low values are near black, high values pale yellow (magma's ends).
  EXPECT_LT(out.pixel(10, 10)[0], 0.01f);
  EXPECT_GT(out.pixel(150, 10)[0], 0.9f);
  EXPECT_GT(out.pixel(150, 10)[2], 0.4f);
  // The bar runs from dark to bright across the image.
  EXPECT_LT(out.pixel(0, 102)[0], out.pixel(199, 102)[0]);
  // The labels are drawn in white below the bar.
  int white = 0;
  for (int y = 100; y < out.height(); ++y)
    for (int x = 0; x < out.width(); ++x) white += out.pixel(x, y)[0] == 1.0f;
  EXPECT_GT(white, 10);
}

TEST(FalseColor, MagmaIsMonotonicInLuminance) {
  float previous = -1;
  for (int i = 0; i <= 100; ++i) {
    float rgb[3];
    magmaSrgb(float(i) / 100.0f, rgb);
    float y = float(kLuminanceRed) * rgb[0] + float(kLuminanceGreen) * rgb[1] +
              float(kLuminanceBlue) * rgb[2];
    EXPECT_GT(y, previous);
    previous = y;
  }
}

}  // namespace
}  // namespace gib::image
