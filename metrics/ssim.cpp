#include "metrics/ssim.h"

#include "metrics/tone_map.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <array>
#include <cmath>
#include <vector>

namespace gib::metrics {

namespace {

constexpr int kRadius = 5;  // 11-pixel window
constexpr double kSigma = 1.5;
constexpr double kC1 = 0.01 * 0.01;  // (K1·L)² with L = 1
constexpr double kC2 = 0.03 * 0.03;  // (K2·L)²

std::array<float, 2 * kRadius + 1> gaussianWeights() {
  std::array<float, 2 * kRadius + 1> w{};
  double sum = 0;
  for (int i = -kRadius; i <= kRadius; ++i) sum += std::exp(-0.5 * i * i / (kSigma * kSigma));
  for (int i = -kRadius; i <= kRadius; ++i)
    w[i + kRadius] = float(std::exp(-0.5 * i * i / (kSigma * kSigma)) / sum);
  return w;
}

// Separable Gaussian blur with clamp-to-edge addressing.
std::vector<float> blur(const std::vector<float>& in, int width, int height) {
  static const auto w = gaussianWeights();
  std::vector<float> tmp(in.size()), out(in.size());
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](auto rows) {
    for (int y = rows.begin(); y != rows.end(); ++y)
      for (int x = 0; x < width; ++x) {
        float s = 0;
        for (int k = -kRadius; k <= kRadius; ++k)
          s += w[k + kRadius] * in[std::size_t(y) * width + std::clamp(x + k, 0, width - 1)];
        tmp[std::size_t(y) * width + x] = s;
      }
  });
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](auto rows) {
    for (int y = rows.begin(); y != rows.end(); ++y)
      for (int x = 0; x < width; ++x) {
        float s = 0;
        for (int k = -kRadius; k <= kRadius; ++k)
          s += w[k + kRadius] * tmp[std::size_t(std::clamp(y + k, 0, height - 1)) * width + x];
        out[std::size_t(y) * width + x] = s;
      }
  });
  return out;
}

std::vector<float> displayLuminance(const image::Image& image) {
  std::vector<float> y(image.pixelCount());
  for (std::size_t i = 0; i < y.size(); ++i) {
    const float* p = image.data().data() + 3 * i;
    auto encode = [](float v) { return std::isfinite(v) ? displayEncode(v) : 0.0f; };
    y[i] = 0.2126f * encode(p[0]) + 0.7152f * encode(p[1]) + 0.0722f * encode(p[2]);
  }
  return y;
}

}  // namespace

MetricValue computeSsim(const image::Image& reference, const image::Image& test) {
  requireComparable(reference, test);
  const int width = reference.width(), height = reference.height();
  const std::vector<float> x = displayLuminance(reference);
  const std::vector<float> y = displayLuminance(test);
  std::vector<float> xx(x.size()), yy(x.size()), xy(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    xx[i] = x[i] * x[i];
    yy[i] = y[i] * y[i];
    xy[i] = x[i] * y[i];
  }
  // Local means and second moments under the Gaussian window.
  const std::vector<float> mx = blur(x, width, height), my = blur(y, width, height);
  const std::vector<float> mxx = blur(xx, width, height), myy = blur(yy, width, height);
  const std::vector<float> mxy = blur(xy, width, height);

  MetricValue result;
  result.map = image::Image(width, height, 1);
  double sum = 0;
  std::size_t count = 0;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const std::size_t k = std::size_t(j) * width + i;
      const double sx = double(mxx[k]) - double(mx[k]) * mx[k];
      const double sy = double(myy[k]) - double(my[k]) * my[k];
      const double sxy = double(mxy[k]) - double(mx[k]) * my[k];
      const double s = (2 * double(mx[k]) * my[k] + kC1) * (2 * sxy + kC2) /
                       ((double(mx[k]) * mx[k] + double(my[k]) * my[k] + kC1) * (sx + sy + kC2));
      result.map.pixel(i, j)[0] = float(s);
      const bool inside =
          i >= kRadius && j >= kRadius && i < width - kRadius && j < height - kRadius;
      if (inside) {
        sum += s;
        ++count;
      }
    }
  // Images smaller than the window: average the whole map instead.
  if (count == 0)
    for (float v : result.map.data()) {
      sum += v;
      ++count;
    }
  result.value = sum / double(count);
  return result;
}

}  // namespace gib::metrics
