#include "metrics/image_metrics.h"

#include "metrics/error_concentration.h"

#include "metrics/tone_map.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace gib::metrics {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

bool pixelIsFinite(const float* p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

// The per-pixel map of `channel_error` averaged over R, G, B, and the mean over finite pixels.
// Rows run in parallel; each row's sum (in double) is kept and the rows are added in order, so
// the result is the same whatever the number of threads.
template <typename ChannelError>
MetricValue perPixelMean(const image::Image& reference, const image::Image& test,
                         ChannelError channel_error) {
  requireComparable(reference, test);
  MetricValue result;
  result.map = image::Image(reference.width(), reference.height(), 1);
  std::vector<double> row_sums(std::size_t(reference.height()), 0.0);
  std::vector<std::size_t> row_counts(std::size_t(reference.height()), 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, reference.height()), [&](auto rows) {
    for (int y = rows.begin(); y != rows.end(); ++y)
      for (int x = 0; x < reference.width(); ++x) {
        const float* r = reference.pixel(x, y);
        const float* t = test.pixel(x, y);
        float& out = result.map.pixel(x, y)[0];
        if (!pixelIsFinite(r) || !pixelIsFinite(t)) {
          out = kNaN;
          continue;
        }
        double e =
            (channel_error(r[0], t[0]) + channel_error(r[1], t[1]) + channel_error(r[2], t[2])) /
            3.0;
        out = float(e);
        row_sums[std::size_t(y)] += e;
        ++row_counts[std::size_t(y)];
      }
  });
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t y = 0; y < row_sums.size(); ++y) {
    sum += row_sums[y];
    count += row_counts[y];
  }
  result.value = count > 0 ? sum / double(count) : kNaN;
  return result;
}

}  // namespace

void requireComparable(const image::Image& reference, const image::Image& test) {
  if (reference.channels() != 3 || test.channels() != 3)
    throw std::invalid_argument("image metrics need 3-channel RGB images");
  if (reference.width() != test.width() || reference.height() != test.height())
    throw std::invalid_argument("image metrics need images of the same size");
}

MetricValue computeMse(const image::Image& reference, const image::Image& test) {
  return perPixelMean(reference, test, [](double r, double t) { return (t - r) * (t - r); });
}

MetricValue computeRmse(const image::Image& reference, const image::Image& test) {
  MetricValue mse = computeMse(reference, test);
  for (float& v : mse.map.data()) v = std::sqrt(v);
  mse.value = std::sqrt(mse.value);
  return mse;
}

MetricValue computeMae(const image::Image& reference, const image::Image& test) {
  return perPixelMean(reference, test, [](double r, double t) { return std::abs(t - r); });
}

MetricValue computeRelMse(const image::Image& reference, const image::Image& test, double epsilon,
                          bool reject_outliers) {
  MetricValue result = perPixelMean(reference, test, [epsilon](double r, double t) {
    return (t - r) * (t - r) / (r * r + epsilon);
  });
  // Without the largest 0.1% of the per-pixel values (fireflies).
  if (reject_outliers)
    result.value = errorConcentration(result.map, kRelMseRejectedFraction).mean_without;
  return result;
}

MetricValue computeMape(const image::Image& reference, const image::Image& test, double epsilon) {
  return perPixelMean(reference, test, [epsilon](double r, double t) {
    return std::abs(t - r) / (std::abs(r) + epsilon);
  });
}

MetricValue computeSmape(const image::Image& reference, const image::Image& test, double epsilon) {
  return perPixelMean(reference, test, [epsilon](double r, double t) {
    return 2.0 * std::abs(t - r) / (std::abs(t) + std::abs(r) + epsilon);
  });
}

MetricValue computePsnr(const image::Image& reference, const image::Image& test) {
  MetricValue mse = perPixelMean(reference, test, [](float r, float t) {
    double d = double(displayEncode(t)) - double(displayEncode(r));
    return d * d;
  });
  MetricValue result;
  result.value =
      mse.value > 0 ? 10.0 * std::log10(1.0 / mse.value) : std::numeric_limits<double>::infinity();
  return result;
}

std::size_t countNonFiniteInEither(const image::Image& reference, const image::Image& test) {
  requireComparable(reference, test);
  std::size_t count = 0;
  for (int y = 0; y < reference.height(); ++y)
    for (int x = 0; x < reference.width(); ++x)
      count += !pixelIsFinite(reference.pixel(x, y)) || !pixelIsFinite(test.pixel(x, y));
  return count;
}

MetricValue computeEnergyRatio(const image::Image& reference, const image::Image& test) {
  requireComparable(reference, test);
  // Serial and in pixel order, so the sums do not depend on the thread count.
  double reference_sum = 0, test_sum = 0;
  for (int y = 0; y < reference.height(); ++y)
    for (int x = 0; x < reference.width(); ++x) {
      const float* r = reference.pixel(x, y);
      const float* t = test.pixel(x, y);
      if (!pixelIsFinite(r) || !pixelIsFinite(t)) continue;
      reference_sum += image::rec709Luminance(r);
      test_sum += image::rec709Luminance(t);
    }
  MetricValue result;
  result.value = reference_sum > 0 ? test_sum / reference_sum : kNaN;
  return result;
}

}  // namespace gib::metrics
