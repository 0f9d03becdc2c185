// The (0,2)-sequence of Sobol's first two dimensions, randomised by Owen scrambling
// (docs/architecture.md, "Randomness"). Owen scrambling keeps the net structure of the points
// (every aligned block of 2^m points is a (0,m,2)-net: one point in each of the 2^m elementary
// rectangles of any shape) while making each point uniform in [0,1)², so estimates stay
// unbiased and independent scramblings give independent estimates.
//
// The scramble is the hash form of Laine & Karras (2011): a bijection of 32-bit words in which
// each bit, counted from the most significant, is flipped by a function of the seed and of the
// bits above it only, which is what nested uniform scrambling asks of a base-2 digit. Addition,
// multiplication by an odd number and xor with a multiple of an even number only carry towards
// higher bits, so applied to the bit-reversed word they give that dependence. The constants are
// Vegdahl's (2021), whose scrambles pass avalanche tests the original ones fail.
#pragma once

#include <array>
#include <cstdint>

namespace gib::ref {

// Reverses the bits within each byte, then the bytes with one instruction (x86 has no bit
// reversal).
constexpr std::uint32_t reverseBits(std::uint32_t v) {
  v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
  v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
  v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
  return __builtin_bswap32(v);
}

// The scramble in bit-reversed order: bit i of the result depends on bits 0…i of `v` only.
constexpr std::uint32_t scrambleReversed(std::uint32_t v, std::uint32_t seed) {
  v ^= v * 0x3d20adeau;
  v += seed;
  v *= (seed >> 16) | 1u;
  v ^= v * 0x05526c56u;
  v ^= v * 0x53a22864u;
  return v;
}

// Nested uniform (Owen) scramble of a 0.32 fixed-point value: bit 31 − i of the result depends
// on the seed and bits 31 … 31 − i of `v`.
constexpr std::uint32_t owenScramble(std::uint32_t v, std::uint32_t seed) {
  return reverseBits(scrambleReversed(reverseBits(v), seed));
}

// Sobol's second dimension, bit-reversed (what the scramble in reversed order takes): the index
// times the Pascal matrix mod 2, whose columns reversed are the tables' entries. Linear over
// GF(2), so it is the xor of four byte tables' entries.
class SobolSecondDimensionReversed {
 public:
  constexpr SobolSecondDimensionReversed() {
    // Column j of the generator matrix is the direction number v_j (v_0 = 2³¹, v_j = v_{j−1} ^
    // v_{j−1} >> 1); a table entry is the xor of the columns of its byte's set bits.
    std::uint32_t v[32] = {};
    v[0] = 1u << 31;
    for (int j = 1; j < 32; ++j) v[j] = v[j - 1] ^ (v[j - 1] >> 1);
    for (int byte = 0; byte < 4; ++byte)
      for (int value = 0; value < 256; ++value) {
        std::uint32_t x = 0;
        for (int bit = 0; bit < 8; ++bit)
          if (value & (1 << bit)) x ^= v[8 * byte + bit];
        tables_[byte][value] = reverseBits(x);
      }
  }
  constexpr std::uint32_t operator()(std::uint32_t index) const {
    return tables_[0][index & 0xff] ^ tables_[1][(index >> 8) & 0xff] ^
           tables_[2][(index >> 16) & 0xff] ^ tables_[3][index >> 24];
  }

 private:
  std::array<std::array<std::uint32_t, 256>, 4> tables_{};
};

inline constexpr SobolSecondDimensionReversed kSobolSecondDimensionReversed{};

// A 0.32 fixed-point value as a float in [0, 1): the top 24 bits, so 1.0f never occurs.
constexpr float fixedToUnitFloat(std::uint32_t v) {
  return float(v >> 8) * 0x1p-24f;
}

}  // namespace gib::ref
