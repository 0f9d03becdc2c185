// SSIM (Wang, Bovik, Sheikh & Simoncelli 2004) on the luminance of the display-mapped images
// (tone_map.h), with the paper's parameters: an 11 × 11 Gaussian window of σ = 1.5,
// K1 = 0.01, K2 = 0.03 and dynamic range L = 1.
#pragma once

#include "metrics/image_metrics.h"

namespace gib::metrics {

// The map covers every pixel (the window is clamped at the borders); the mean is taken, as in
// the paper's reference code, over the pixels whose window lies inside the image. Non-finite
// pixels read as 0 after the display mapping; the caller reports them separately.
MetricValue computeSsim(const image::Image& reference, const image::Image& test);

}  // namespace gib::metrics
