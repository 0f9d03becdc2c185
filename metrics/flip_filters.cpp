#include "metrics/flip_filters.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gib::metrics::flip_detail {
namespace {

// Contrast sensitivity functions of the colour pipeline, CSF(f) = Σ a·exp(−b·f²) with f in
// cycles per degree, whose spatial-domain filters are a·√(π/b)·exp(−π²x²/b) with x in degrees
// (FLIP paper, spatial filtering; Y and Cx one term, Cz two). Values from the paper, as
// NVlabs/flip v1.6 uses them.
constexpr double kYA = 1.0, kYB = 0.0047;
constexpr double kCxA = 1.0, kCxB = 0.0053;
constexpr double kCzFirstA = 34.1, kCzFirstB = 0.04;
constexpr double kCzSecondA = 13.5, kCzSecondB = 0.025;
// The kernels reach three standard deviations of the widest Gaussian (largest b); a term
// exp(−π²x²/b) has standard deviation √(b / (2π²)) degrees (FLIP paper, spatial filtering).
constexpr double kWidestB = kCzFirstB;
constexpr double kSpatialRadiusInSigmas = 3.0;

// Feature detection: w = 0.082 degrees, the width of the edge detector; the Gaussian's standard
// deviation is w/2, and the kernel reaches 3σ (FLIP paper, feature pipeline).
constexpr double kFeatureWidthDegrees = 0.082;
constexpr double kFeatureRadiusInSigmas = 3.0;

// One axis of the separable 2-D filter term a·√(π/b)·exp(−π²(x² + y²)/b): the square root of the
// amplitude times exp(−π²x²/b), so that the outer product of two of them is the 2-D term. The
// amplitude matters only between the two Cz terms; normalisation removes it otherwise.
double filterTermOneAxis(double x_deg, double a, double b) {
  constexpr double kPi = std::numbers::pi;
  return std::sqrt(a * std::sqrt(kPi / b)) * std::exp(-kPi * kPi * x_deg * x_deg / b);
}

// Scales the positive taps to sum 1 and the negative ones to sum −1, so that a derivative filter
// answers a unit step with 1 whatever its width.
void normalizeSigned(std::vector<double>& taps) {
  double positive = 0, negative = 0;
  for (double t : taps) (t > 0 ? positive : negative) += std::fabs(t);
  for (double& t : taps) {
    if (t > 0) t /= positive;
    if (t < 0) t /= negative;
  }
}

Kernel toKernel(int radius, const std::vector<double>& taps, double scale) {
  Kernel kernel{radius, std::vector<float>(taps.size())};
  for (std::size_t i = 0; i < taps.size(); ++i) kernel.taps[i] = float(taps[i] * scale);
  return kernel;
}

}  // namespace

SpatialKernels makeSpatialKernels(float pixels_per_degree) {
  const double ppd = pixels_per_degree;
  const double sigma_deg = std::sqrt(kWidestB / (2.0 * std::numbers::pi * std::numbers::pi));
  const int radius = int(std::ceil(kSpatialRadiusInSigmas * sigma_deg * ppd));
  const int width = 2 * radius + 1;

  // Step 1: sample each term at pixel centres, x = i / ppd degrees.
  std::vector<double> y(width), cx(width), cz_first(width), cz_second(width);
  for (int i = 0; i < width; ++i) {
    const double x = (i - radius) / ppd;
    y[i] = filterTermOneAxis(x, kYA, kYB);
    cx[i] = filterTermOneAxis(x, kCxA, kCxB);
    cz_first[i] = filterTermOneAxis(x, kCzFirstA, kCzFirstB);
    cz_second[i] = filterTermOneAxis(x, kCzSecondA, kCzSecondB);
  }

  // Step 2: normalise. A separable kernel sums to (Σ 1-D)², so Y and Cx divide by their 1-D sum;
  // the Cz pair sums to S₁² + S₂², so both divide by √(S₁² + S₂²).
  auto sum = [](const std::vector<double>& v) {
    double s = 0;
    for (double t : v) s += t;
    return s;
  };
  const double cz_norm = std::hypot(sum(cz_first), sum(cz_second));
  return {toKernel(radius, y, 1.0 / sum(y)), toKernel(radius, cx, 1.0 / sum(cx)),
          toKernel(radius, cz_first, 1.0 / cz_norm), toKernel(radius, cz_second, 1.0 / cz_norm)};
}

FeatureKernels makeFeatureKernels(float pixels_per_degree) {
  const double sigma_px = 0.5 * kFeatureWidthDegrees * double(pixels_per_degree);
  const int radius = int(std::ceil(kFeatureRadiusInSigmas * sigma_px));
  const int width = 2 * radius + 1;

  std::vector<double> gaussian(width), first(width), second(width);
  double gaussian_sum = 0;
  for (int i = 0; i < width; ++i) {
    const double x = i - radius;
    const double g = std::exp(-x * x / (2.0 * sigma_px * sigma_px));
    gaussian[i] = g;
    gaussian_sum += g;
    // d/dx and d²/dx² of the Gaussian up to positive factors, which the normalisation removes.
    first[i] = -x * g;
    second[i] = (x * x / (sigma_px * sigma_px) - 1.0) * g;
  }
  normalizeSigned(first);
  normalizeSigned(second);
  return {toKernel(radius, gaussian, 1.0 / gaussian_sum), toKernel(radius, first, 1.0),
          toKernel(radius, second, 1.0)};
}

void padRow(const float* row, int width, int radius, float* padded) {
  std::fill(padded, padded + radius, row[0]);
  std::copy(row, row + width, padded + radius);
  std::fill(padded + radius + width, padded + 2 * radius + width, row[width - 1]);
}

void convolvePaddedRow(const float* padded, int width, const Kernel& kernel, float* out) {
  std::fill(out, out + width, 0.0f);
  // Tap-major order: the inner loop runs over x and vectorises; each output still sums its taps
  // from left to right, so the result does not depend on how rows are split among threads.
  for (std::size_t j = 0; j < kernel.taps.size(); ++j) {
    const float weight = kernel.taps[j];
    const float* source = padded + j;
    for (int x = 0; x < width; ++x) out[x] += weight * source[x];
  }
}

void convolveColumn(const float* plane, int width, int height, int y, const Kernel& kernel,
                    float* out) {
  std::fill(out, out + width, 0.0f);
  for (int j = 0; j <= 2 * kernel.radius; ++j) {
    const int row = std::clamp(y + j - kernel.radius, 0, height - 1);
    const float weight = kernel.taps[std::size_t(j)];
    const float* source = plane + std::size_t(row) * std::size_t(width);
    for (int x = 0; x < width; ++x) out[x] += weight * source[x];
  }
}

}  // namespace gib::metrics::flip_detail
