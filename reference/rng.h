// Counter-based randomness (docs/architecture.md, "Randomness"): every random number is a pure
// function of (seed, pixel, sample, dimension), so results do not depend on thread count or tile
// order, and a pixel's samples can be regenerated in isolation.
#pragma once

#include "common/splitmix.h"

#include <cstdint>

namespace gib::ref {

// The random stream of one (seed, pixel, sample). Dimensions are consumed in order along the
// path; the stream itself holds no hidden state beyond the dimension counter.
class SampleStream {
 public:
  SampleStream(std::uint64_t seed, std::uint32_t pixel, std::uint32_t sample)
      : key_(splitMixFinalise(splitMixFinalise((std::uint64_t(pixel) << 32) | sample) ^
                              splitMix64(seed))) {}

  // Uniform in [0, 1): 24 random bits, so 1 − 2⁻²⁴ is the largest value and 1.0f never occurs.
  float next() {
    return float(splitMixFinalise(key_ + kGoldenGamma * ++dimension_) >> 40) * 0x1p-24f;
  }

  std::uint32_t dimension() const { return dimension_; }

 private:
  std::uint64_t key_;
  std::uint32_t dimension_ = 0;
};

}  // namespace gib::ref
