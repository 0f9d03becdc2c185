// The reference's sampler (docs/architecture.md, "Randomness"): low-discrepancy points for the
// decisions of one path, a pure function of (seed, pixel, sample, dimension).
//
// Each dimension of the path (the pixel position, then a fixed set per scattering vertex) draws
// from its own copy of the Owen-scrambled (0,2)-sequence (reference/owen_sobol.h), with the
// sample index shuffled by its own scramble: "padding", which keeps every 2D pair stratified
// while leaving different pairs uncorrelated, however deep the path. The shuffle maps the first
// 2^m indices of a pixel onto an aligned block of the sequence, so every power-of-two prefix of a
// pixel's samples is a (0,m,2)-net in each pair, and progressive checkpoints stay prefixes.
//
// A render is split into independently scrambled replicas: sample s of a pixel is sample s / K
// of replica s % K. The spread of the K replica means estimates the variance of the pixel mean
// even though the samples within a replica are correlated (reference/progressive_renderer.h).
#pragma once

#include "reference/owen_sobol.h"
#include "reference/rng.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <optional>

namespace gib::ref {

// The dimensions of one scattering vertex, in the order the path tracer uses them. Each is one
// 2D pair; the 1D decisions use its first coordinate.
enum class VertexDimension : std::uint32_t {
  kFreeFlight,        // delta tracking's first draw on the segment that reaches the vertex
  kLightPoint,        // which area light triangle (x), then the point on it (reused x, y)
  kLightShadow,       // ratio tracking's first draw on the shadow ray to it
  kSkyDirection,      // the sky sample's direction
  kSkyShadow,         // ratio tracking's first draw towards the sky
  kDeltaLightShadow,  // ratio tracking towards spot and directional light j, for j below:
  kDirection = kDeltaLightShadow + 4,  // the BSDF lobe (x), then the direction (reused x, y)
  kRoulette,
  kCount
};
inline constexpr std::uint32_t kDeltaLightShadowDimensions = 4;

// kSobol: the low-discrepancy points above. kIndependent: independent uniform numbers in the same
// layout, the classic Monte Carlo sampler, kept to measure what the points buy side by side.
enum class SamplerKind { kSobol, kIndependent };

class PathSampler {
 public:
  PathSampler(std::uint64_t seed, std::uint32_t pixel, std::uint32_t sample, std::uint32_t replicas,
              SamplerKind kind = SamplerKind::kSobol)
      : key_(splitMixFinalise(splitMix64(seed) ^ splitMixFinalise((std::uint64_t(pixel) << 32) |
                                                                  (sample % replicas)))),
        index_(sample / replicas),
        reversed_index_(reverseBits(index_)),
        sobol_(kind == SamplerKind::kSobol),
        seed_(seed),
        pixel_(pixel),
        sample_(sample) {}

  // The sample's position inside its pixel.
  glm::vec2 pixelPosition() const { return point2D(0); }
  // The sample's point on a thin lens (scene::cameraRay). A dimension past every vertex's rather
  // than after the pixel's, so that the vertices keep their dimensions and a pinhole render (which
  // never draws it) its pixels, bit for bit.
  glm::vec2 lensPosition() const { return point2D(kLensDimension); }

  // Selects the dimensions of scattering vertex `vertex` (0: the first the camera ray reaches).
  void startVertex(int vertex) {
    base_ = 1 + std::uint32_t(vertex) * std::uint32_t(VertexDimension::kCount);
  }
  float get1D(VertexDimension d) const { return point1D(base_ + std::uint32_t(d)); }
  glm::vec2 get2D(VertexDimension d) const { return point2D(base_ + std::uint32_t(d)); }
  // Ratio tracking's first draw towards delta light j (an independent number past the slots).
  float deltaLightShadow(std::size_t j) {
    return j < kDeltaLightShadowDimensions
               ? point1D(base_ + std::uint32_t(VertexDimension::kDeltaLightShadow) +
                         std::uint32_t(j))
               : independent().next();
  }

  // For decisions whose number is not known in advance (the draws of a tracking walk after its
  // first): an independent stream of the same (seed, pixel, sample).
  SampleStream& independent() {
    // Made on first use: paths without a medium (most) never draw from it.
    if (!independent_) independent_.emplace(seed_, pixel_, sample_);
    return *independent_;
  }

  std::uint32_t index() const { return index_; }

 private:
  // The scrambles of dimension d: one for the index shuffle, one per coordinate.
  std::uint64_t dimensionHash(std::uint32_t d) const {
    return splitMixFinalise(key_ + kGoldenGamma * (std::uint64_t(d) + 1));
  }
  // The shuffled index (an Owen scramble of it, so the first 2^m indices land on one aligned
  // block of 2^m points). The reversals are arranged so that each point costs as few as
  // possible: Sobol's first dimension is the reversed index, and its scramble works reversed.
  std::uint32_t shuffledIndex(std::uint64_t hash) const {
    return reverseBits(scrambleReversed(reversed_index_, std::uint32_t(hash)));
  }
  static float firstCoordinate(std::uint32_t j, std::uint64_t hash) {
    return fixedToUnitFloat(reverseBits(scrambleReversed(j, std::uint32_t(hash >> 32))));
  }
  // The independent sampler's numbers: a hash of the dimension's and the index's.
  std::uint64_t independentBits(std::uint64_t hash) const {
    return splitMixFinalise(hash ^ (kGoldenGamma * (std::uint64_t(index_) + 1)));
  }
  float point1D(std::uint32_t d) const {
    const std::uint64_t hash = dimensionHash(d);
    if (!sobol_) return fixedToUnitFloat(std::uint32_t(independentBits(hash)));
    return firstCoordinate(shuffledIndex(hash), hash);
  }
  glm::vec2 point2D(std::uint32_t d) const {
    const std::uint64_t hash = dimensionHash(d);
    if (!sobol_) {
      const std::uint64_t bits = independentBits(hash);
      return {fixedToUnitFloat(std::uint32_t(bits)), fixedToUnitFloat(std::uint32_t(bits >> 32))};
    }
    const std::uint32_t j = shuffledIndex(hash);
    // The second coordinate's scramble: the high half of the hash times an odd constant, which
    // depends on all 64 bits of the hash (one multiplication instead of another mixer).
    const std::uint32_t y_seed = std::uint32_t((hash * kGoldenGamma) >> 32);
    return {
        firstCoordinate(j, hash),
        fixedToUnitFloat(reverseBits(scrambleReversed(kSobolSecondDimensionReversed(j), y_seed)))};
  }

  // Beyond the dimensions of any path: vertex v's start at 1 + v · kCount.
  static constexpr std::uint32_t kLensDimension = 0xffffffffu;

  std::uint64_t key_;  // of (seed, pixel, replica)
  std::uint32_t index_;
  std::uint32_t reversed_index_;
  bool sobol_;
  std::uint64_t seed_;
  std::uint32_t pixel_;
  std::uint32_t sample_;
  std::uint32_t base_ = 1;
  std::optional<SampleStream> independent_;
};

}  // namespace gib::ref
