#include "metrics/ssim.h"

#include "reference/rng.h"

#include <gtest/gtest.h>

namespace gib::metrics {
namespace {

image::Image makeTexture() {
  image::Image image(64, 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      for (int c = 0; c < 3; ++c) image.pixel(x, y)[c] = ((x / 4 + y / 4) % 2) ? 0.8f : 0.1f;
  return image;
}

image::Image addNoise(const image::Image& in, float amplitude) {
  image::Image out = in;
  std::uint32_t i = 0;
  for (float& v : out.data()) {
    ref::SampleStream random(11, i++, 0);
    v += amplitude * (2 * random.next() - 1);
  }
  return out;
}

TEST(Ssim, AnImageWithItselfIsExactlyOne) {
  const image::Image a = makeTexture();
  MetricValue s = computeSsim(a, a);
  EXPECT_EQ(s.value, 1.0);
  for (float v : s.map.data()) EXPECT_EQ(v, 1.0f);
}

TEST(Ssim, FallsAsNoiseGrows) {
  const image::Image a = makeTexture();
  double previous = 1.0;
  for (float amplitude : {0.02f, 0.05f, 0.1f, 0.2f}) {
    double s = computeSsim(a, addNoise(a, amplitude)).value;
    EXPECT_LT(s, previous) << amplitude;
    previous = s;
  }
  EXPECT_LT(previous, 0.95);
}

TEST(Ssim, ABrightnessShiftCostsLessThanStructureLoss) {
  const image::Image a = makeTexture();
  image::Image shifted = a;
  for (float& v : shifted.data()) v *= 1.1f;
  image::Image flat(64, 64, 3, 0.45f);
  EXPECT_GT(computeSsim(a, shifted).value, computeSsim(a, flat).value);
}

}  // namespace
}  // namespace gib::metrics
