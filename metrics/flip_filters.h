// FLIP's filters as separable 1-D kernels, and the row and column passes that apply them with
// clamp-to-edge borders. Private to metrics/flip*.cpp.
#pragma once

#include <vector>

namespace gib::metrics::flip_detail {

// A symmetric 1-D kernel of 2·radius + 1 taps; taps[radius] is the centre.
struct Kernel {
  int radius = 0;
  std::vector<float> taps;
};

// The contrast sensitivity filters of the colour pipeline (FLIP paper, spatial filtering), one
// per YyCxCz channel. Y and Cx are single Gaussians, each 1-D kernel normalised to sum 1 so that
// its outer product does. Cz is a sum of two Gaussians, which is not separable as a whole but is
// as the sum of two separable terms: cz_first ⊗ cz_first + cz_second ⊗ cz_second, scaled
// together so that the 2-D sum is 1. All four share the radius of the widest Gaussian.
struct SpatialKernels {
  Kernel y, cx, cz_first, cz_second;
};
SpatialKernels makeSpatialKernels(float pixels_per_degree);

// The feature detectors of the feature pipeline (FLIP paper, edges and points): a Gaussian of
// standard deviation 0.5·w·ppd pixels, normalised to sum 1, and its first and second derivatives,
// each with its positive taps scaled to sum 1 and its negative taps to sum −1. The 2-D edge
// filter in x is first ⊗ gaussian (x then y), the point filter second ⊗ gaussian; y likewise.
struct FeatureKernels {
  Kernel gaussian, first, second;
};
FeatureKernels makeFeatureKernels(float pixels_per_degree);

// Copies a row of `width` values into `padded` (width + 2·radius values), repeating the edge
// values outward: the clamp-to-edge border of every FLIP filter.
void padRow(const float* row, int width, int radius, float* padded);

// out[x] = Σ_j taps[j] · padded[x + j] for x in [0, width): a row pass over a padded row.
void convolvePaddedRow(const float* padded, int width, const Kernel& kernel, float* out);

// out[x] = Σ_j taps[j] · plane[clamp(y + j − radius), x]: a column pass producing row y of a
// width × height plane, rows clamped to the image.
void convolveColumn(const float* plane, int width, int height, int y, const Kernel& kernel,
                    float* out);

}  // namespace gib::metrics::flip_detail
