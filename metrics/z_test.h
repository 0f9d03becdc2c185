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
};

struct ZTestResult {
  bool passed = false;
  std::size_t tested = 0;   // pixel channels with a usable variance
  std::size_t failing = 0;  // of those, the ones whose p-value is below the corrected level
  double per_value_significance = 0;  // Šidák-corrected over `tested`
  double min_p_value = 1;
  image::Image p_values;  // one channel: the smallest p-value over R, G, B per pixel
};

// Two-sided test per pixel channel of z = (test − mean) / sqrt(var_ref + var_test). `test_variance`
// may be empty (a deterministic test image). Values with zero total variance count as failing
// when they differ and are not tested otherwise. Throws std::invalid_argument on size mismatch.
ZTestResult zTest(const image::Image& reference_mean, const image::Image& reference_variance,
                  const image::Image& test, const image::Image& test_variance,
                  const ZTestOptions& options = {});

}  // namespace gib::metrics
