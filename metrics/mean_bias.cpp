#include "metrics/mean_bias.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace gib::metrics {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool pixelIsFinite(const float* p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

// Sums of both images' channels over the pixels of [x0, x1) × [y0, y1) finite in both.
struct Sums {
  std::array<double, 3> reference{};
  std::array<double, 3> test{};
  std::size_t count = 0;
};

Sums sumRegion(const image::Image& reference, const image::Image& test, int x0, int x1, int y0,
               int y1) {
  Sums sums;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const float* r = reference.pixel(x, y);
      const float* t = test.pixel(x, y);
      if (!pixelIsFinite(r) || !pixelIsFinite(t)) continue;
      for (int c = 0; c < 3; ++c) {
        sums.reference[c] += r[c];
        sums.test[c] += t[c];
      }
      ++sums.count;
    }
  return sums;
}

ChannelMeans meansOf(const Sums& sums) {
  ChannelMeans means;
  for (int c = 0; c < 3; ++c) {
    means.reference[c] = sums.count > 0 ? sums.reference[c] / double(sums.count) : kNaN;
    means.test[c] = sums.count > 0 ? sums.test[c] / double(sums.count) : kNaN;
  }
  return means;
}

}  // namespace

ChannelMeans computeChannelMeans(const image::Image& reference, const image::Image& test) {
  requireComparable(reference, test);
  return meansOf(sumRegion(reference, test, 0, reference.width(), 0, reference.height()));
}

MetricValue computeBlockBias(const image::Image& reference, const image::Image& test) {
  const ChannelMeans image_means = computeChannelMeans(reference, test);
  MetricValue result;
  result.map = image::Image(reference.width(), reference.height(), 1, float(kNaN));
  for (int y0 = 0; y0 < reference.height(); y0 += kBiasBlockSize)
    for (int x0 = 0; x0 < reference.width(); x0 += kBiasBlockSize) {
      const int x1 = std::min(x0 + kBiasBlockSize, reference.width());
      const int y1 = std::min(y0 + kBiasBlockSize, reference.height());
      const ChannelMeans block = meansOf(sumRegion(reference, test, x0, x1, y0, y1));
      double worst = kNaN;
      for (int c = 0; c < 3; ++c) {
        // Also false for NaN: a block without finite pixels, an image without light.
        if (!(block.reference[c] >= kBiasBlockFloor * image_means.reference[c] &&
              block.reference[c] > 0))
          continue;
        const double difference = std::abs(block.test[c] - block.reference[c]) / block.reference[c];
        worst = std::isnan(worst) ? difference : std::max(worst, difference);
      }
      if (!std::isnan(worst)) result.value = std::max(result.value, worst);
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) result.map.pixel(x, y)[0] = float(worst);
    }
  return result;
}

}  // namespace gib::metrics
