// The Z-test accepts an unbiased image at its stated rate and rejects a biased one.
#include "metrics/z_test.h"

#include "reference/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace gib::metrics {
namespace {

constexpr int kSize = 32;
constexpr double kStandardError = 0.05;  // of each per-pixel mean

double gaussian(ref::SampleStream& random) {
  double u1 = 1.0 - random.next(), u2 = random.next();
  return std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
}

// A per-pixel mean estimate of a smooth true image, with the given standard error and bias.
image::Image estimate(std::uint64_t seed, double bias) {
  image::Image image(kSize, kSize);
  std::uint32_t i = 0;
  for (float& v : image.data()) {
    ref::SampleStream random(seed, i, 0);
    double truth = 0.5 + 0.3 * std::sin(0.1 * i++);
    v = float(truth + bias + kStandardError * gaussian(random));
  }
  return image;
}

TEST(ZTest, AcceptsUnbiasedImagesAtTheStatedRate) {
  // At a family-wise significance of 1%, 200 independent unbiased trials reject ~2 times; more
  // than 8 has probability ≈ 0.1% under Binomial(200, 0.01).
  const image::Image variance(kSize, kSize, 3, float(kStandardError * kStandardError));
  int rejected = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const image::Image reference = estimate(1000 + trial, 0.0);
    const image::Image test = estimate(5000 + trial, 0.0);
    ZTestResult r = zTest(reference, variance, test, variance);
    EXPECT_EQ(r.tested, std::size_t(kSize * kSize * 3));
    rejected += !r.passed;
  }
  EXPECT_LE(rejected, 8);
}

TEST(ZTest, RejectsABiasedImage) {
  // A bias of 3 standard errors (of the difference) on every pixel: ~10% of the values exceed
  // the corrected threshold (|z| ≈ 4.3), so every trial must fail.
  const image::Image variance(kSize, kSize, 3, float(kStandardError * kStandardError));
  for (int trial = 0; trial < 20; ++trial) {
    const image::Image reference = estimate(1000 + trial, 0.0);
    const image::Image test = estimate(9000 + trial, 3 * std::sqrt(2.0) * kStandardError);
    ZTestResult r = zTest(reference, variance, test, variance);
    EXPECT_FALSE(r.passed) << "trial " << trial;
    EXPECT_GT(r.failing, 10u);
  }
}

TEST(ZTest, ToleratesAStatedFractionOfFailures) {
  const image::Image variance(kSize, kSize, 3, float(kStandardError * kStandardError));
  const image::Image reference = estimate(1, 0.0);
  image::Image test = estimate(2, 0.0);
  test.pixel(0, 0)[0] += 10.0f;  // one firefly
  EXPECT_FALSE(zTest(reference, variance, test, variance).passed);
  ZTestOptions lenient;
  lenient.max_failing_fraction = 0.001;
  EXPECT_TRUE(zTest(reference, variance, test, variance, lenient).passed);
}

TEST(ZTest, NanFailsAndDeterministicEqualityPasses) {
  const image::Image zero(4, 4, 3, 0.0f);
  image::Image a(4, 4, 3, 0.5f);
  EXPECT_TRUE(zTest(a, zero, a, image::Image()).passed);
  image::Image b = a;
  b.pixel(1, 1)[1] = std::nanf("");
  ZTestResult r = zTest(a, zero, b, image::Image());
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.failing, 1u);
}

}  // namespace
}  // namespace gib::metrics
