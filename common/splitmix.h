// SplitMix64 (Steele, Lea & Flood 2014), the project's one counter-based hash: every random number
// is a pure function of its inputs (docs/architecture.md, "Randomness"), so results do not depend
// on thread count, tile order or what ran before.
#pragma once

#include <cstdint>

namespace gib {

// SplitMix64's increment, 2⁶⁴/φ rounded to odd: consecutive counters land far apart.
inline constexpr std::uint64_t kGoldenGamma = 0x9e3779b97f4a7c15ull;

// SplitMix64's finaliser: a bijective 64-bit mixer with good avalanche.
constexpr std::uint64_t splitMixFinalise(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// One step of SplitMix64 from state z: the increment, then the finaliser.
constexpr std::uint64_t splitMix64(std::uint64_t z) {
  return splitMixFinalise(z + kGoldenGamma);
}

// The seed of a render independent of one made with `seed` (a convergence series' test images,
// a store entry's verification): far from it in every stream the counter-based hash derives.
constexpr std::uint64_t independentSeed(std::uint64_t seed) {
  return seed + kGoldenGamma;
}

}  // namespace gib
