#include "metrics/z_test.h"

#include "metrics/distributions.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace gib::metrics {

namespace {

// Welch–Satterthwaite: the degrees of freedom of a sum of two variance estimates with `a_dof` and
// `b_dof` (0: exact, infinite). Infinity when both are exact.
double welchDegreesOfFreedom(double a, double a_dof, double b, double b_dof) {
  const double a_term = a_dof > 0 ? a * a / a_dof : 0.0;
  const double b_term = b_dof > 0 ? b * b / b_dof : 0.0;
  if (a_term + b_term <= 0) return std::numeric_limits<double>::infinity();
  return (a + b) * (a + b) / (a_term + b_term);
}

double twoSidedPValue(double z, double dof) {
  // Normal: 2·(1 − Φ(|z|)) = erfc(|z|/√2), which keeps its precision in the far tail.
  // Beyond a million degrees of freedom t and normal agree to far better than the tests need.
  if (!std::isfinite(dof) || dof > 1e6) return std::erfc(z / std::sqrt(2.0));
  return 2.0 * studentTCdf(-z, dof);
}

}  // namespace

double differencePValue(double difference, double a, double a_dof, double b, double b_dof) {
  return twoSidedPValue(std::abs(difference) / std::sqrt(a + b),
                        welchDegreesOfFreedom(a, a_dof, b, b_dof));
}

namespace {

// The values a Z-test compares: per value, the difference and the two variances with their
// degrees of freedom; and per pixel, the row of values (a pixel or its block) it belongs to.
struct TestValues {
  std::vector<double> difference, a, a_dof, b, b_dof;
  std::vector<std::size_t> row_of_pixel;
};

TestValues pixelValues(const image::Image& reference_mean, const image::Image& reference_variance,
                       const image::Image& test, const image::Image& test_variance,
                       const ZTestOptions& options) {
  const bool has_test_variance = test_variance.pixelCount() > 0;
  TestValues v;
  for (std::size_t i = 0; i < reference_mean.data().size(); ++i) {
    v.difference.push_back(double(test.data()[i]) - reference_mean.data()[i]);
    v.a.push_back(reference_variance.data()[i]);
    v.a_dof.push_back(options.reference_variance_dof);
    v.b.push_back(has_test_variance ? test_variance.data()[i] : 0.0);
    v.b_dof.push_back(options.test_variance_dof);
  }
  for (std::size_t p = 0; p < reference_mean.pixelCount(); ++p) v.row_of_pixel.push_back(p);
  return v;
}

// Block means of independent pixels: the mean's variance is Σ var / n², its degrees of freedom
// those of a sum of independent variance estimates (Welch–Satterthwaite; 0 stays exact).
struct BlockSum {
  double difference = 0, a = 0, a_terms = 0, b = 0, b_terms = 0;
  int n = 0;
  void add(double d, double va, double va_dof, double vb, double vb_dof) {
    difference += d;
    a += va;
    b += vb;
    if (va_dof > 0) a_terms += va * va / va_dof;
    if (vb_dof > 0) b_terms += vb * vb / vb_dof;
    ++n;
  }
};

double sumDegreesOfFreedom(double sum, double terms) {
  return terms > 0 ? sum * sum / terms : 0.0;
}

TestValues blockValues(const TestValues& pixels, int width, int height, int channels, int block) {
  TestValues v;
  const int blocks_x = (width + block - 1) / block, blocks_y = (height + block - 1) / block;
  v.row_of_pixel.resize(std::size_t(width) * height);
  std::vector<BlockSum> sums(std::size_t(blocks_x) * blocks_y * channels);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t pixel = std::size_t(y) * width + x;
      const std::size_t row = std::size_t(y / block) * blocks_x + std::size_t(x / block);
      v.row_of_pixel[pixel] = row;
      for (int c = 0; c < channels; ++c) {
        const std::size_t i = pixel * channels + c;
        sums[row * channels + c].add(pixels.difference[i], pixels.a[i], pixels.a_dof[i],
                                     pixels.b[i], pixels.b_dof[i]);
      }
    }
  for (const BlockSum& s : sums) {
    const double n = s.n, n2 = n * n;
    v.difference.push_back(s.difference / n);
    v.a.push_back(s.a / n2);
    v.a_dof.push_back(sumDegreesOfFreedom(s.a, s.a_terms));
    v.b.push_back(s.b / n2);
    v.b_dof.push_back(sumDegreesOfFreedom(s.b, s.b_terms));
  }
  return v;
}

}  // namespace

ZTestResult zTest(const image::Image& reference_mean, const image::Image& reference_variance,
                  const image::Image& test, const image::Image& test_variance,
                  const ZTestOptions& options) {
  if (!reference_mean.sameSize(reference_variance) || !reference_mean.sameSize(test) ||
      (test_variance.pixelCount() > 0 && !reference_mean.sameSize(test_variance)))
    throw std::invalid_argument("the Z-test needs mean, variance and test images of one size");
  if (options.block < 1) throw std::invalid_argument("the Z-test's block must be at least 1");

  const int channels = reference_mean.channels();
  TestValues values = pixelValues(reference_mean, reference_variance, test, test_variance, options);
  if (options.block > 1)
    values = blockValues(values, reference_mean.width(), reference_mean.height(), channels,
                         options.block);

  ZTestResult result;
  // Per value: its p-value, and whether it fails whatever the significance (a NaN, or a
  // difference where neither image has any variance).
  std::vector<double> p_values(values.difference.size(), 1.0);
  std::vector<bool> tested(p_values.size(), false);
  std::size_t always_failing = 0;
  for (std::size_t i = 0; i < p_values.size(); ++i) {
    const double difference = values.difference[i];
    const double variance = values.a[i] + values.b[i];
    if (!std::isfinite(difference) || !std::isfinite(variance) ||
        (variance <= 0 && difference != 0)) {
      p_values[i] = 0;
      ++always_failing;
      continue;
    }
    if (variance <= 0) continue;  // identical and deterministic: nothing to test
    p_values[i] =
        differencePValue(difference, values.a[i], values.a_dof[i], values.b[i], values.b_dof[i]);
    tested[i] = true;
    ++result.tested;
  }
  result.per_value_significance =
      sidakSignificance(options.significance, double(std::max<std::size_t>(result.tested, 1)));
  result.failing = always_failing;
  for (std::size_t i = 0; i < p_values.size(); ++i) {
    result.min_p_value = std::min(result.min_p_value, p_values[i]);
    if (tested[i] && p_values[i] < result.per_value_significance) ++result.failing;
  }
  result.p_values = image::Image(reference_mean.width(), reference_mean.height(), 1, 1.0f);
  for (std::size_t p = 0; p < values.row_of_pixel.size(); ++p)
    for (int c = 0; c < channels; ++c)
      result.p_values.data()[p] = std::min(result.p_values.data()[p],
                                           float(p_values[values.row_of_pixel[p] * channels + c]));
  const double allowed = options.max_failing_fraction * double(result.tested + always_failing);
  result.passed = double(result.failing) <= allowed;
  return result;
}

}  // namespace gib::metrics
