// Per-pixel error metrics between a reference and a test image: linear float RGB of equal size.
// Each returns the scalar and a one-channel map of the per-pixel value (the channel mean).
// Pixels where either image has a NaN or infinite channel are left out of every average (their
// map value is NaN) and counted by countNonFiniteInEither: never silently averaged.
#pragma once

#include "image/image.h"

#include <cstddef>

namespace gib::metrics {

struct MetricValue {
  double value = 0;
  image::Image map;  // one channel; empty for metrics without a per-pixel form
};

// ε of relMSE, MAPE and SMAPE: keeps dark reference pixels from dominating (a common choice in
// rendering papers for radiance of order 1).
inline constexpr double kRelativeEpsilon = 1e-2;
// relMSE with outlier rejection drops this fraction of the largest per-pixel values.
inline constexpr double kRelMseRejectedFraction = 0.001;

MetricValue computeMse(const image::Image& reference, const image::Image& test);
MetricValue computeRmse(const image::Image& reference, const image::Image& test);
MetricValue computeMae(const image::Image& reference, const image::Image& test);
// (x − r)² / (r² + ε), averaged; with `reject_outliers`, the top 0.1% of pixels are dropped.
MetricValue computeRelMse(const image::Image& reference, const image::Image& test,
                          double epsilon = kRelativeEpsilon, bool reject_outliers = false);
// |x − r| / (|r| + ε)
MetricValue computeMape(const image::Image& reference, const image::Image& test,
                        double epsilon = kRelativeEpsilon);
// 2|x − r| / (|x| + |r| + ε), in [0, 2)
MetricValue computeSmape(const image::Image& reference, const image::Image& test,
                         double epsilon = kRelativeEpsilon);
// 10·log10(1 / MSE) of the display-mapped images (tone_map.h), in dB; +inf for equal images.
MetricValue computePsnr(const image::Image& reference, const image::Image& test);
// Energy: the mean luminance of `test` over the mean luminance of `reference`, over the pixels
// finite in both (1 = the same light in the image; radiosity's lost or gained energy shows here).
// No map. NaN when the reference is black.
MetricValue computeEnergyRatio(const image::Image& reference, const image::Image& test);

// Pixels with a non-finite channel in either image.
std::size_t countNonFiniteInEither(const image::Image& reference, const image::Image& test);

// Throws std::invalid_argument unless both are 3-channel images of the same size.
void requireComparable(const image::Image& reference, const image::Image& test);

}  // namespace gib::metrics
