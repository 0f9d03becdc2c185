// The Z-test accepts an unbiased image at its stated rate and rejects a biased one.
#include "metrics/z_test.h"

#include "reference/rng.h"
#include "support/statistical_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace gib::metrics {
namespace {

constexpr int kSize = 32;
constexpr double kStandardError = 0.05;  // of each per-pixel mean
constexpr int kTrials = 200;             // of each rejection rate below

// A correct Z-test rejects unbiased images more often than its significance allows in one of
// this file's two rate tests (with known variances, with estimated ones) with probability 1%.
constexpr test::TestFamily kFamily(0.01, 2);

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
  // At its family-wise significance (1% by default) the Z-test rejects independent unbiased
  // trials with that probability or less (Binomial(200, 0.01): ~2 of them).
  const ZTestOptions options;
  const image::Image variance(kSize, kSize, 3, float(kStandardError * kStandardError));
  std::size_t rejected = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    const image::Image reference = estimate(1000 + trial, 0.0);
    const image::Image test = estimate(5000 + trial, 0.0);
    ZTestResult r = zTest(reference, variance, test, variance, options);
    EXPECT_EQ(r.tested, std::size_t(kSize * kSize * 3));
    rejected += !r.passed;
  }
  EXPECT_TRUE(kFamily.binomialAtMost(rejected, kTrials, options.significance));
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

// A per-pixel mean of `replicas` normal replica means, and its variance estimated from their
// spread (replicas − 1 degrees of freedom), as the reference renderer estimates it.
struct ReplicaEstimate {
  image::Image mean, variance;
};
ReplicaEstimate replicaEstimate(std::uint64_t seed, int replicas) {
  ReplicaEstimate e{image::Image(kSize, kSize), image::Image(kSize, kSize)};
  const double replica_sd = kStandardError * std::sqrt(double(replicas));
  for (std::uint32_t i = 0; i < e.mean.data().size(); ++i) {
    ref::SampleStream random(seed, i, 0);
    const double truth = 0.5 + 0.3 * std::sin(0.1 * i);
    double sum = 0, sum_squares = 0;
    for (int r = 0; r < replicas; ++r) {
      const double x = truth + replica_sd * gaussian(random);
      sum += x;
      sum_squares += x * x;
    }
    const double mean = sum / replicas;
    e.mean.data()[i] = float(mean);
    e.variance.data()[i] =
        float((sum_squares - replicas * mean * mean) / (replicas - 1) / replicas);
  }
  return e;
}

TEST(ZTest, EstimatedVariancesNeedTheirDegreesOfFreedom) {
  // Variances from 8 replicas (7 dof each). Read as exact, the statistic's tails are Student's,
  // far heavier than the normal's: most unbiased trials fail. With the degrees of freedom given,
  // the rejection rate is the stated 1%.
  ZTestOptions with_dof;
  with_dof.reference_variance_dof = with_dof.test_variance_dof = 7;
  std::size_t rejected_as_exact = 0, rejected_with_dof = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    const ReplicaEstimate a = replicaEstimate(100 + trial, 8), b = replicaEstimate(700 + trial, 8);
    rejected_as_exact += !zTest(a.mean, a.variance, b.mean, b.variance).passed;
    rejected_with_dof += !zTest(a.mean, a.variance, b.mean, b.variance, with_dof).passed;
  }
  EXPECT_TRUE(kFamily.binomialAtMost(rejected_with_dof, kTrials, with_dof.significance));
  EXPECT_GT(rejected_as_exact, std::size_t(kTrials / 2));
}

TEST(ZTest, DifferencePValueIsStudentsTWithWelchDegreesOfFreedom) {
  // Equal variances of equal dof ν: Welch gives 2ν, so |t| = 2.145 is the two-sided 5% point
  // of t₁₄ for ν = 7; exact variances give the normal's 1.96.
  EXPECT_NEAR(differencePValue(2.1448 * std::sqrt(2.0), 1, 7, 1, 7), 0.05, 1e-4);
  EXPECT_NEAR(differencePValue(1.95996, 1, 0, 0, 0), 0.05, 1e-5);
  // One exact variance holding half the total: (1 + 1)² / (1²/7) = 28 dof, whose 5% point is
  // 2.048.
  EXPECT_NEAR(differencePValue(2.0484 * std::sqrt(2.0), 1, 7, 1, 0), 0.05, 1e-4);
}

TEST(ZTest, BlocksAverageIndependentPixelsAndTheirVariances) {
  // 2×2 blocks of a 4×2 image: two blocks. Each block's mean difference is the average of its
  // pixels', its variance the sum over n² (n = 4), so a uniform offset of 1 with per-pixel
  // variance 1 becomes z = 1 / √(4/16) = 2 per block.
  const image::Image reference(4, 2, 3, 0.0f), variance(4, 2, 3, 1.0f);
  const image::Image test(4, 2, 3, 1.0f);
  ZTestOptions blocks;
  blocks.block = 2;
  const ZTestResult r = zTest(reference, variance, test, image::Image(), blocks);
  EXPECT_EQ(r.tested, 2u * 3u);
  EXPECT_NEAR(r.min_p_value, std::erfc(2 / std::sqrt(2.0)), 1e-12);
  // The map gives each pixel its block's p-value.
  EXPECT_FLOAT_EQ(r.p_values.pixel(3, 1)[0], float(std::erfc(2 / std::sqrt(2.0))));
  // A partial block at the edge averages the pixels it has.
  ZTestOptions wide;
  wide.block = 3;
  EXPECT_EQ(zTest(reference, variance, test, image::Image(), wide).tested, 2u * 3u);
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
