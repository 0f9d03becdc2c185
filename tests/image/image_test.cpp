#include "image/image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace gib::image {
namespace {

TEST(Image, DefaultIsEmptyRgb) {
  const Image image;
  EXPECT_EQ(image.width(), 0);
  EXPECT_EQ(image.height(), 0);
  EXPECT_EQ(image.channels(), 3);
  EXPECT_EQ(image.pixelCount(), 0u);
  EXPECT_TRUE(image.data().empty());
}

TEST(Image, ConstructsFilled) {
  const Image image(4, 2, 3, 0.5f);
  EXPECT_EQ(image.pixelCount(), 8u);
  ASSERT_EQ(image.data().size(), 24u);
  for (float value : image.data()) EXPECT_EQ(value, 0.5f);
}

TEST(Image, PixelsAreRowMajorInterleavedFromTopLeft) {
  Image image(3, 2, 4);
  image.pixel(2, 1)[3] = 7.0f;
  image.pixel(1, 0)[0] = 5.0f;
  // Pixel (x, y) starts at (y * width + x) * channels.
  EXPECT_EQ(image.data()[(1 * 3 + 2) * 4 + 3], 7.0f);
  EXPECT_EQ(image.data()[(0 * 3 + 1) * 4 + 0], 5.0f);
  const Image& constant = image;
  EXPECT_EQ(constant.pixel(2, 1)[3], 7.0f);
}

TEST(Image, RejectsInvalidSize) {
  EXPECT_THROW(Image(-1, 2), std::invalid_argument);
  EXPECT_THROW(Image(2, -1), std::invalid_argument);
  EXPECT_THROW(Image(2, 2, 0), std::invalid_argument);
}

TEST(Image, SameSizeComparesWidthHeightAndChannels) {
  const Image image(4, 3, 3);
  EXPECT_TRUE(image.sameSize(Image(4, 3, 3, 1.0f)));
  EXPECT_FALSE(image.sameSize(Image(3, 4, 3)));
  EXPECT_FALSE(image.sameSize(Image(4, 3, 1)));
}

TEST(Image, CountNonFiniteCountsPixelsNotValues) {
  Image image(4, 1, 3, 1.0f);
  EXPECT_EQ(countNonFinite(image), 0u);
  image.pixel(0, 0)[0] = std::numeric_limits<float>::quiet_NaN();
  image.pixel(0, 0)[2] = std::numeric_limits<float>::infinity();  // Same pixel: counted once.
  image.pixel(2, 0)[1] = -std::numeric_limits<float>::infinity();
  image.pixel(3, 0)[2] = std::numeric_limits<float>::max();  // Large but finite.
  EXPECT_EQ(countNonFinite(image), 2u);
}

}  // namespace
}  // namespace gib::image
