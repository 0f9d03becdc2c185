// Closed-form cases for every per-pixel metric: a constant offset, a scaled image, known noise.
#include "metrics/image_metrics.h"

#include "metrics/tone_map.h"
#include "reference/rng.h"
#include "support/statistical_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace gib::metrics {
namespace {

// A correct metric misses one of this file's two statistical tests (Gaussian noise's MSE and
// MAE) with probability 1%.
constexpr test::TestFamily kFamily(0.01, 2);

// A smooth positive image with values between 0.1 and 1.1.
image::Image makeReference(int width = 64, int height = 48) {
  image::Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c)
        image.pixel(x, y)[c] = 0.1f + float(x + 2 * y + 7 * c) / float(width + 2 * height + 14);
  return image;
}

image::Image transform(const image::Image& in, float scale, float offset) {
  image::Image out = in;
  for (float& v : out.data()) v = scale * v + offset;
  return out;
}

TEST(ImageMetrics, ConstantOffsetGivesItsSquareAndAbsoluteValue) {
  const image::Image r = makeReference();
  const image::Image t = transform(r, 1.0f, 0.05f);
  EXPECT_NEAR(computeMse(r, t).value, 0.0025, 1e-8);
  EXPECT_NEAR(computeRmse(r, t).value, 0.05, 1e-6);
  EXPECT_NEAR(computeMae(r, t).value, 0.05, 1e-6);
  // The maps hold the per-pixel value.
  EXPECT_NEAR(computeMse(r, t).map.pixel(3, 4)[0], 0.0025f, 1e-7f);
}

TEST(ImageMetrics, ScaledImageGivesClosedFormRelativeErrors) {
  // t = s·r: relMSE per value (s−1)²r²/(r²+ε), MAPE (s−1)r/(r+ε), SMAPE 2(s−1)r/((s+1)r+ε).
  const image::Image r = makeReference();
  const double s = 1.2, eps = kRelativeEpsilon;
  const image::Image t = transform(r, float(s), 0.0f);
  double relmse = 0, mape = 0, smape = 0;
  for (float v : r.data()) {
    double x = v;
    double tx = double(float(s) * v);  // as transform() computes it, in float
    relmse += (tx - x) * (tx - x) / (x * x + eps);
    mape += std::abs(tx - x) / (x + eps);
    smape += 2 * std::abs(tx - x) / (tx + x + eps);
  }
  const double n = double(r.data().size());
  EXPECT_NEAR(computeRelMse(r, t).value, relmse / n, 1e-9);
  EXPECT_NEAR(computeMape(r, t).value, mape / n, 1e-9);
  EXPECT_NEAR(computeSmape(r, t).value, smape / n, 1e-9);
  // And the relative error is independent of the scale of the image when ε is negligible.
  const image::Image r10 = transform(r, 10.0f, 0.0f), t10 = transform(t, 10.0f, 0.0f);
  EXPECT_NEAR(computeMape(r10, t10).value, 0.2, 1e-3);
}

TEST(ImageMetrics, GaussianNoiseGivesItsVarianceAsMse) {
  // n = 64·48·3 noise values of σ = 0.1: the MSE estimates σ² with standard error σ²·√(2/n), the
  // MAE σ·√(2/π) with standard error σ·√((1 − 2/π)/n).
  const image::Image r = makeReference();
  image::Image t = r;
  std::uint32_t i = 0;
  for (float& v : t.data()) {
    ref::SampleStream random(3, i++, 0);
    // Box–Muller from two uniforms.
    double u1 = 1.0 - random.next(), u2 = random.next();
    v += float(0.1 * std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2));
  }
  const double n = double(r.data().size());
  EXPECT_TRUE(kFamily.zTest(computeMse(r, t).value, 0.01, 0.01 * std::sqrt(2 / n)));
  EXPECT_TRUE(kFamily.zTest(computeMae(r, t).value, 0.1 * std::sqrt(2 / std::numbers::pi),
                            0.1 * std::sqrt((1 - 2 / std::numbers::pi) / n)));
}

TEST(ImageMetrics, EnergyRatioIsTheRatioOfMeanLuminances) {
  const image::Image r = makeReference();
  EXPECT_NEAR(computeEnergyRatio(r, transform(r, 0.8f, 0.0f)).value, 0.8, 1e-6);
  EXPECT_NEAR(computeEnergyRatio(r, r).value, 1.0, 1e-12);
  // Light moved from one pixel to another keeps the energy; a non-finite pixel is left out of
  // both means.
  image::Image moved = r;
  moved.pixel(0, 0)[1] += 0.5f;
  moved.pixel(5, 5)[1] -= 0.5f;
  EXPECT_NEAR(computeEnergyRatio(r, moved).value, 1.0, 1e-6);
  image::Image broken = r;
  broken.pixel(2, 2)[0] = std::numeric_limits<float>::infinity();
  EXPECT_NEAR(computeEnergyRatio(r, broken).value, 1.0, 1e-12);
  EXPECT_TRUE(std::isnan(computeEnergyRatio(transform(r, 0.0f, 0.0f), r).value));
}

TEST(ImageMetrics, PsnrOfAConstantDisplayOffset) {
  // A reference in the sRGB curve's linear toe region (≤ 0.0031308) and a test offset there by
  // δ: display values differ by 12.92·δ, so PSNR = −20·log10(12.92·δ).
  image::Image r(16, 16, 3, 0.001f);
  image::Image t(16, 16, 3, 0.002f);
  EXPECT_NEAR(computePsnr(r, t).value, -20 * std::log10(12.92 * 0.001), 1e-3);
  EXPECT_TRUE(std::isinf(computePsnr(r, r).value));
}

TEST(ImageMetrics, IdenticalImagesHaveZeroError) {
  const image::Image r = makeReference();
  EXPECT_EQ(computeMse(r, r).value, 0.0);
  EXPECT_EQ(computeRelMse(r, r).value, 0.0);
  EXPECT_EQ(computeSmape(r, r).value, 0.0);
}

TEST(ImageMetrics, OutlierRejectionDropsTheTopTenthOfAPercent) {
  const image::Image r = makeReference(100, 100);
  image::Image t = r;
  for (int k = 0; k < 10; ++k) t.pixel(k, 0)[0] = 1000.0f;  // 10 fireflies of 10⁴ pixels
  const double with = computeRelMse(r, t).value;
  const double without = computeRelMse(r, t, kRelativeEpsilon, true).value;
  EXPECT_GT(with, 100.0);
  EXPECT_EQ(without, 0.0);
}

TEST(ImageMetrics, NonFinitePixelsAreCountedNotAveraged) {
  const image::Image r = makeReference();
  image::Image t = transform(r, 1.0f, 0.05f);
  t.pixel(1, 1)[0] = std::numeric_limits<float>::quiet_NaN();
  t.pixel(2, 2)[2] = std::numeric_limits<float>::infinity();
  EXPECT_EQ(countNonFiniteInEither(r, t), 2u);
  MetricValue mse = computeMse(r, t);
  EXPECT_NEAR(mse.value, 0.0025, 1e-8) << "the two bad pixels must not change the mean";
  EXPECT_TRUE(std::isnan(mse.map.pixel(1, 1)[0]));
}

TEST(ImageMetrics, MismatchedSizesAreRejected) {
  EXPECT_THROW(computeMse(makeReference(8, 8), makeReference(8, 9)), std::invalid_argument);
}

}  // namespace
}  // namespace gib::metrics
