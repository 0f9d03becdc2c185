// Bias that pixel noise hides. Two unbiased renders of one scene differ pixel by pixel by their
// noise, but their means over many pixels converge to the same values; a difference that
// survives the averaging is systematic (a wrong light unit, a one-sided emitter rendered
// two-sided). So two renderers are compared by their image means and by their means over blocks.
#pragma once

#include "image/image.h"
#include "metrics/image_metrics.h"

#include <array>

namespace gib::metrics {

struct ChannelMeans {
  std::array<double, 3> reference{};
  std::array<double, 3> test{};
};

// Per-channel means over the pixels finite in both images (NaN when there are none).
ChannelMeans computeChannelMeans(const image::Image& reference, const image::Image& test);

// Blocks are this many pixels wide and high; those at the right and bottom edges may be smaller.
inline constexpr int kBiasBlockSize = 16;
// A block's channel is left out when its reference mean is below this fraction of the channel's
// image mean: a relative difference of near-black measures noise over nothing.
inline constexpr double kBiasBlockFloor = 0.01;

// The largest |t − r| / r over the channels of every block, r and t the block's means over the
// pixels finite in both images. The map gives each pixel its block's largest value (NaN where
// no channel of the block counts). 0 when no block counts.
MetricValue computeBlockBias(const image::Image& reference, const image::Image& test);

}  // namespace gib::metrics
