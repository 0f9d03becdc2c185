// Image and block means: a systematic difference shows, noise that averages out and black
// regions do not.
#include "metrics/mean_bias.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace gib::metrics {
namespace {

image::Image constant(int width, int height, float r, float g, float b) {
  image::Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      image.pixel(x, y)[0] = r;
      image.pixel(x, y)[1] = g;
      image.pixel(x, y)[2] = b;
    }
  return image;
}

TEST(MeanBias, ChannelMeansSkipPixelsNotFiniteInBoth) {
  image::Image reference = constant(4, 2, 1, 2, 3);
  image::Image test = constant(4, 2, 2, 4, 6);
  test.pixel(0, 0)[0] = std::numeric_limits<float>::quiet_NaN();
  reference.pixel(1, 0)[0] = 100;  // counts: finite in both
  const ChannelMeans means = computeChannelMeans(reference, test);
  EXPECT_DOUBLE_EQ(means.reference[0], (6 * 1 + 100) / 7.0);
  EXPECT_DOUBLE_EQ(means.test[1], 4);
  EXPECT_DOUBLE_EQ(means.test[2], 6);
}

TEST(MeanBias, BlockBiasFindsTheBlockThatDiffers) {
  // 40×20: blocks of 16 with partial ones at the right and bottom edges.
  const image::Image reference = constant(40, 20, 1, 1, 1);
  image::Image test = reference;
  // Zero-mean "noise" inside one block leaves it unbiased ...
  for (int x = 0; x < 16; ++x) test.pixel(x, 3)[1] = x % 2 ? 1.5f : 0.5f;
  // ... a 5% excess of blue in the partial block at the bottom right does not.
  for (int y = 16; y < 20; ++y)
    for (int x = 32; x < 40; ++x) test.pixel(x, y)[2] = 1.05f;
  const MetricValue bias = computeBlockBias(reference, test);
  EXPECT_NEAR(bias.value, 0.05, 1e-6);
  EXPECT_NEAR(bias.map.pixel(39, 19)[0], 0.05f, 1e-6f);
  EXPECT_EQ(bias.map.pixel(0, 0)[0], 0.0f);
}

TEST(MeanBias, BlocksDarkerThanTheFloorDoNotCount) {
  // The left block is black in the reference and the right one bright: the left one's
  // difference, however large relatively, is noise over nothing.
  image::Image reference = constant(32, 16, 1, 1, 1);
  image::Image test = reference;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      for (int c = 0; c < 3; ++c) {
        reference.pixel(x, y)[c] = 1e-4f;
        test.pixel(x, y)[c] = 2e-4f;
      }
  const MetricValue bias = computeBlockBias(reference, test);
  EXPECT_EQ(bias.value, 0.0);
  EXPECT_TRUE(std::isnan(bias.map.pixel(0, 0)[0]));
}

}  // namespace
}  // namespace gib::metrics
