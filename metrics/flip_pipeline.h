// The LDR-FLIP pipeline on planar YyCxCz images, shared by LDR-FLIP and the exposures of
// HDR-FLIP, and the pooling of an error map into FlipResult's statistics. Private to
// metrics/flip*.cpp.
#pragma once

#include <array>
#include <vector>

#include "metrics/flip.h"
#include "metrics/flip_filters.h"

namespace gib::metrics::flip_detail {

// One image in YyCxCz, one plane per channel, row-major.
struct OpponentImage {
  std::vector<float> y, cx, cz;
};

// Evaluates LDR-FLIP of reference() against test() for one image size and viewing distance.
// It owns every intermediate plane, so HDR-FLIP reuses them across its exposures.
class LdrFlipEvaluator {
 public:
  LdrFlipEvaluator(int width, int height, float pixels_per_degree);

  int width() const { return width_; }
  int height() const { return height_; }
  // The inputs: display-linear RGB in [0, 1] converted to YyCxCz, width × height per plane.
  OpponentImage& reference() { return images_[0]; }
  OpponentImage& test() { return images_[1]; }

  // Writes the FLIP error of every pixel, width × height values in [0, 1], into `error`.
  void evaluate(float* error);

 private:
  void computeColorDifference(float* color_difference);
  void combineWithFeatureDifference(float* error);

  int width_;
  int height_;
  SpatialKernels spatial_;
  FeatureKernels feature_;
  std::array<OpponentImage, 2> images_;
  // Row-pass results, four per image: the colour pipeline's Y, Cx and the two Cz terms, later
  // the feature pipeline's first-derivative, second-derivative and Gaussian rows.
  std::array<std::array<std::vector<float>, 4>, 2> row_passes_;
};

// Fills the statistics of `result` from its error_map: mean, weighted quartiles, minimum and
// maximum (FlipResult documents them). Deterministic: sums run in a fixed order.
void poolErrors(FlipResult& result);

}  // namespace gib::metrics::flip_detail
