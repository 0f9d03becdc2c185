// FLIP, the perceptual difference of two images as a viewer flipping between them sees it:
// LDR-FLIP (Andersson et al. 2020, "FLIP: A Difference Evaluator for Alternating Images", HPG)
// and HDR-FLIP (Andersson et al. 2021, "Visualizing Errors in Rendered High Dynamic Range
// Images", Eurographics short papers). The results follow NVlabs/flip v1.6, the authors'
// published implementation, within 1e-3 on the mean (docs/flip-validation.md says how that was
// checked and with which numbers).
//
// Inputs are linear Rec.709 RGB (docs/architecture.md, "Radiometry"); only the first three channels
// are read, so RGBA images work too. A pixel with a NaN or infinite channel is evaluated as black
// (0, 0, 0): callers count such pixels with image::countNonFinite and report them apart, and
// FLIP stays finite instead of spreading the NaN through its filters.
#pragma once

#include <optional>

#include "image/image.h"

namespace gib::metrics {

// How large a pixel looks: the filters' widths are set in degrees of visual angle.
struct FlipViewingConditions {
  // The papers' default: a 0.7 m wide 3840-pixel monitor seen from 0.7 m, rounded to 67, the figure
  // the HPG 2020 paper quotes. The published tool computes it unrounded, 67.0206
  // (flipPixelsPerDegree(0.7, 0.7, 3840)); the difference moves means by about 2e-5.
  double pixels_per_degree = 67.0;
};

// Pixels per degree of visual angle for a display of `display_width_m` metres and
// `horizontal_resolution_px` pixels seen from `distance_m` metres, as the FLIP paper defines it:
// distance · (resolution / width) · π / 180 (the small-angle approximation).
double flipPixelsPerDegree(double distance_m, double display_width_m,
                           double horizontal_resolution_px);

struct FlipResult {
  // One channel, the per-pixel FLIP error in [0, 1]; same width and height as the inputs.
  image::Image error_map;
  double mean = 0;
  // Weighted percentiles as the published tool pools them: each pixel weighs as much as its
  // error, so the p-th weighted percentile is the smallest error e (of the sorted errors) at
  // which the running sum of errors exceeds p times their total; 0 when every error is 0.
  double weighted_median = 0;
  double weighted_first_quartile = 0;
  double weighted_third_quartile = 0;
  double minimum = 0, maximum = 0;
  // HDR-FLIP only (0 for LDR-FLIP): the exposure range in stops and the number of exposures
  // evaluated, evenly spaced from start to stop inclusive.
  double start_exposure = 0, stop_exposure = 0;
  int exposure_count = 0;
};

// LDR-FLIP. Both images are display-linear RGB, clamped to [0, 1]: exactly what the published
// tool computes internally after decoding sRGB. Throws std::invalid_argument when the widths or
// heights differ, an image has fewer than three channels, or the images are empty.
FlipResult computeLdrFlip(const image::Image& reference, const image::Image& test,
                          const FlipViewingConditions& viewing = {});

// The exposures HDR-FLIP evaluates, in stops (a factor 2^exposure on the radiance).
struct FlipExposureRange {
  double start_exposure = 0;
  double stop_exposure = 0;
  int exposure_count = 0;
};

struct HdrFlipOptions {
  // Each one left empty is computed from the reference (computeFlipExposureRange).
  std::optional<double> start_exposure = {}, stop_exposure = {};
  std::optional<int> exposure_count = {};
};

// The automatic exposure range of HDR-FLIP (HDR-FLIP paper, exposure range; ACES tone mapper):
// start is the exposure that tone-maps the brightest luminance of the reference to 0.85, stop the
// one that tone-maps its median luminance to 0.85; the count is max(2, ⌈stop − start⌉).
// Luminance is Y = 0.2126 R + 0.7152 G + 0.0722 B. The median is the upper median (element n/2
// of the sorted luminances), as the published tool takes it. Where the median is not positive
// (an image mostly black), the smallest positive luminance stands in for it; with no positive
// luminance at all the range is [0, 0] with two exposures. Non-finite pixels count as black.
FlipExposureRange computeFlipExposureRange(const image::Image& reference);

// HDR-FLIP: the per-pixel maximum of LDR-FLIP over the exposures of the range, each exposure
// scaling both images by 2^exposure, tone-mapping them with ACES (the fit the published tool
// uses) and clamping to [0, 1]. Options override the automatic range. Throws
// std::invalid_argument like computeLdrFlip, and for start > stop, a count below 1, or a
// non-finite start or stop; a count of 1 evaluates the start exposure alone.
FlipResult computeHdrFlip(const image::Image& reference, const image::Image& test,
                          const FlipViewingConditions& viewing = {},
                          const HdrFlipOptions& options = {});

}  // namespace gib::metrics
