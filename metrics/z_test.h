// Per-pixel Z-test of an image against a reference mean and variance, as Mitsuba 3's render
// tests do: detects when the reference renderer itself has changed. Variances are those of the
// per-pixel means (the `variance` layer gibench writes).
#pragma once

#include "image/image.h"

#include <cstddef>

namespace gib::metrics {

struct ZTestOptions {
  // Family-wise significance: the chance that an unchanged renderer fails the test.
  double significance = 0.01;
  // The test passes when at most this fraction of the values fail. Zero is the strict test; a
  // small allowance absorbs pixels whose variance estimate is poor (a firefly seen once).
  double max_failing_fraction = 0.0;
  // Degrees of freedom of each variance estimate; 0 takes it as exact. With estimated variances
  // the statistic follows Student's t with the Welch–Satterthwaite degrees of freedom, not the
  // normal: a reference whose variance comes from 8 replicas (7 dof) exceeds 3 standard
  // errors 7 times as often as the normal says.
  double reference_variance_dof = 0;
  double test_variance_dof = 0;
  // Test the means of block × block tiles of pixels instead of single pixels. A pixel's mean of
  // a skewed estimator at a few hundred samples is far from normal (a pixel that missed the rare
  // long paths has a low mean and a low spread at once), so its far tail under-covers; a block
  // of n independent pixels is √n times closer to normal, at the cost of seeing a change
  // confined to one pixel √n times less well (docs/rendering.md, "Error bars").
  int block = 1;
};

struct ZTestResult {
  bool passed = false;
  std::size_t tested = 0;   // pixel (or block) channels with a usable variance
  std::size_t failing = 0;  // of those, the ones whose p-value is below the corrected level
  double per_value_significance = 0;  // Šidák-corrected over `tested`
  double min_p_value = 1;
  image::Image p_values;  // one channel: the smallest p-value over R, G, B per pixel (its block's)
};

// The two-sided p-value of a difference between two estimates whose variances are `a` and `b`
// with `a_dof` and `b_dof` degrees of freedom (0: exact): Student's t with the Welch–Satterthwaite
// degrees of freedom, the normal when both are exact. The variance sum must be positive.
double differencePValue(double difference, double a, double a_dof, double b, double b_dof);

// Two-sided test per pixel channel of z = (test − mean) / sqrt(var_ref + var_test), against the
// normal or, with estimated variances, Student's t. `test_variance`
// may be empty (a deterministic test image). Values with zero total variance count as failing
// when they differ and are not tested otherwise. Throws std::invalid_argument on size mismatch.
ZTestResult zTest(const image::Image& reference_mean, const image::Image& reference_variance,
                  const image::Image& test, const image::Image& test_variance,
                  const ZTestOptions& options = {});

}  // namespace gib::metrics
