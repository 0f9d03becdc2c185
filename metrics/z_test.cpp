#include "metrics/z_test.h"

#include "metrics/distributions.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace gib::metrics {

ZTestResult zTest(const image::Image& reference_mean, const image::Image& reference_variance,
                  const image::Image& test, const image::Image& test_variance,
                  const ZTestOptions& options) {
  const bool has_test_variance = test_variance.pixelCount() > 0;
  if (!reference_mean.sameSize(reference_variance) || !reference_mean.sameSize(test) ||
      (has_test_variance && !reference_mean.sameSize(test_variance)))
    throw std::invalid_argument("the Z-test needs mean, variance and test images of one size");

  ZTestResult result;
  result.p_values = image::Image(reference_mean.width(), reference_mean.height(), 1, 1.0f);
  const int channels = reference_mean.channels();
  // Per value: its p-value, and whether it fails whatever the significance (a NaN, or a
  // difference where neither image has any variance).
  std::vector<double> p_values(reference_mean.data().size(), 1.0);
  std::vector<bool> tested(p_values.size(), false);
  std::size_t always_failing = 0;
  for (std::size_t i = 0; i < p_values.size(); ++i) {
    const double difference = double(test.data()[i]) - reference_mean.data()[i];
    const double variance =
        double(reference_variance.data()[i]) + (has_test_variance ? test_variance.data()[i] : 0.0);
    if (!std::isfinite(difference) || !std::isfinite(variance) ||
        (variance <= 0 && difference != 0)) {
      p_values[i] = 0;
      ++always_failing;
      continue;
    }
    if (variance <= 0) continue;  // identical and deterministic: nothing to test
    // Two-sided p = 2·(1 − Φ(|z|)) = erfc(|z|/√2), which keeps its precision in the far tail.
    const double z = std::abs(difference) / std::sqrt(variance);
    p_values[i] = std::erfc(z / std::sqrt(2.0));
    tested[i] = true;
    ++result.tested;
  }
  result.per_value_significance =
      sidakSignificance(options.significance, double(std::max<std::size_t>(result.tested, 1)));
  result.failing = always_failing;
  for (std::size_t i = 0; i < p_values.size(); ++i) {
    result.min_p_value = std::min(result.min_p_value, p_values[i]);
    float& map = result.p_values.data()[i / std::size_t(channels)];
    map = std::min(map, float(p_values[i]));
    if (tested[i] && p_values[i] < result.per_value_significance) ++result.failing;
  }
  const double allowed = options.max_failing_fraction * double(result.tested + always_failing);
  result.passed = double(result.failing) <= allowed;
  return result;
}

}  // namespace gib::metrics
