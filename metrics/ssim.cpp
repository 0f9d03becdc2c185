#include "metrics/ssim.h"

#include "common/luminance_shared.h"

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

// Separable Gaussian blur with clamp-to-edge addressing; only the border needs the clamp.
std::vector<float> blur(const std::vector<float>& in, int width, int height) {
  static const auto w = gaussianWeights();
  std::vector<float> tmp(in.size()), out(in.size());
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](auto rows) {
    for (int y = rows.begin(); y != rows.end(); ++y) {
      const float* row = in.data() + std::size_t(y) * width;
      float* target = tmp.data() + std::size_t(y) * width;
      for (int x = 0; x < width; ++x) {
        float s = 0;
        if (x >= kRadius && x < width - kRadius) {
          for (int k = -kRadius; k <= kRadius; ++k) s += w[k + kRadius] * row[x + k];
        } else {
          for (int k = -kRadius; k <= kRadius; ++k)
            s += w[k + kRadius] * row[std::clamp(x + k, 0, width - 1)];
        }
        target[x] = s;
      }
    }
  });
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](auto rows) {
    for (int y = rows.begin(); y != rows.end(); ++y) {
      float* target = out.data() + std::size_t(y) * width;
      std::fill(target, target + width, 0.0f);
      // Whole rows at a time: the inner loop runs along memory and vectorises.
      for (int k = -kRadius; k <= kRadius; ++k) {
        const float* source = tmp.data() + std::size_t(std::clamp(y + k, 0, height - 1)) * width;
        const float weight = w[k + kRadius];
        for (int x = 0; x < width; ++x) target[x] += weight * source[x];
      }
    }
  });
  return out;
}

std::vector<float> displayLuminance(const image::Image& image) {
  std::vector<float> y(image.pixelCount());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, y.size(), 4096), [&](auto range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const float* p = image.data().data() + 3 * i;
      auto encode = [](float v) { return std::isfinite(v) ? displayEncode(v) : 0.0f; };
      y[i] = float(kLuminanceRed) * encode(p[0]) + float(kLuminanceGreen) * encode(p[1]) +
             float(kLuminanceBlue) * encode(p[2]);
    }
  });
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
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](auto rows) {
    for (int j = rows.begin(); j != rows.end(); ++j)
      for (int i = 0; i < width; ++i) {
        const std::size_t k = std::size_t(j) * width + i;
        const double sx = double(mxx[k]) - double(mx[k]) * mx[k];
        const double sy = double(myy[k]) - double(my[k]) * my[k];
        const double sxy = double(mxy[k]) - double(mx[k]) * my[k];
        const double s = (2 * double(mx[k]) * my[k] + kC1) * (2 * sxy + kC2) /
                         ((double(mx[k]) * mx[k] + double(my[k]) * my[k] + kC1) * (sx + sy + kC2));
        result.map.pixel(i, j)[0] = float(s);
      }
  });
  // The mean in pixel order (deterministic), over the pixels whose window lies inside.
  double sum = 0;
  std::size_t count = 0;
  for (int j = kRadius; j < height - kRadius; ++j)
    for (int i = kRadius; i < width - kRadius; ++i) {
      sum += result.map.pixel(i, j)[0];
      ++count;
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
