// How concentrated a mean per-pixel error is: the share of it the worst pixels hold, and the mean
// without them. A real-time frame's error against a path-traced reference is often a few edge
// pixels (a silhouette the rasteriser and the ray tracer cut differently) over a lighting error
// spread thinly: these figures tell the two apart (docs/rendering.md, "Error concentration").
#pragma once

#include "image/image.h"

#include <span>
#include <vector>

namespace gib::metrics {

struct ErrorConcentration {
  double fraction = 0;      // of the finite pixels counted as the worst (0.001: the worst 0.1 %)
  std::size_t worst = 0;    // how many pixels that is: floor(fraction · finite pixels)
  double share = 0;         // their part of the sum of the map (0 when the sum is 0)
  double mean_without = 0;  // the mean of the other pixels
};

// Of a one-channel per-pixel error map (NaN pixels left out, as the metrics do), for each of
// `fractions` from one selection of the worst values. The result is a function of the image
// (not of the thread count); reordering the pixels changes it by rounding only.
std::vector<ErrorConcentration> errorConcentrations(const image::Image& map,
                                                    std::span<const double> fractions);
ErrorConcentration errorConcentration(const image::Image& map, double fraction);

}  // namespace gib::metrics
