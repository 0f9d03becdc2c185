// Counter-based randomness (DESIGN.md, "Randomness"): every random number is a pure function of
// (seed, pixel, sample, dimension), so results do not depend on thread count or tile order, and a
// pixel's samples can be regenerated in isolation.
#pragma once

#include <cstdint>

namespace gib::ref {

// SplitMix64's finaliser: a bijective 64-bit mixer with good avalanche; cheap and stateless.
inline std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// The random stream of one (seed, pixel, sample). Dimensions are consumed in order along the
// path; the stream itself holds no hidden state beyond the dimension counter.
class SampleStream {
 public:
  SampleStream(std::uint64_t seed, std::uint32_t pixel, std::uint32_t sample)
      : key_(mix64(mix64((std::uint64_t(pixel) << 32) | sample) ^ mix64(seed + kGolden))) {}

  // Uniform in [0, 1): 24 random bits, so 1 − 2⁻²⁴ is the largest value and 1.0f never occurs.
  float next() { return float(mix64(key_ + kGolden * ++dimension_) >> 40) * 0x1p-24f; }

  std::uint32_t dimension() const { return dimension_; }

 private:
  static constexpr std::uint64_t kGolden = 0x9e3779b97f4a7c15ull;
  std::uint64_t key_;
  std::uint32_t dimension_ = 0;
};

}  // namespace gib::ref
