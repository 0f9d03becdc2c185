// FLIP throughput on a 1024×768 pair: a compare or a suite job evaluates LDR-FLIP and HDR-FLIP
// on every image, so their cost bounds how many jobs a nightly run can score. Targets on the
// 2-core CI machine: LDR-FLIP under 0.5 s, HDR-FLIP under 3 s.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>

#include "metrics/flip.h"

namespace gib::metrics {
namespace {

constexpr int kWidth_px = 1024;
constexpr int kHeight_px = 768;

// A deterministic value in [0, 1) per (pixel, channel): a counter-based hash, no generator state.
float hashNoise(std::uint32_t x, std::uint32_t y, std::uint32_t c) {
  std::uint32_t h = x * 0x9E3779B1u ^ y * 0x85EBCA77u ^ c * 0xC2B2AE3Du;
  h ^= h >> 16;
  h *= 0x7FEB352Du;
  h ^= h >> 15;
  h *= 0x846CA68Bu;
  h ^= h >> 16;
  return float(h >> 8) * (1.0f / 16777216.0f);
}

// Setup outside the timed loop: a render-like radiance image (gradients, edges, a small bright
// emitter, about nine exposures of dynamic range like the Cornell box) and a noisy version of it,
// the pair a low-sample-count render gives.
class FlipFixture : public benchmark::Fixture {
 public:
  void SetUp(const benchmark::State&) override {
    if (reference_.pixelCount() != 0) return;
    reference_ = image::Image(kWidth_px, kHeight_px, 3);
    test_ = image::Image(kWidth_px, kHeight_px, 3);
    for (int y = 0; y < kHeight_px; ++y)
      for (int x = 0; x < kWidth_px; ++x) {
        const float u = float(x) / kWidth_px;
        const float v = float(y) / kHeight_px;
        const bool tile = ((x / 32) + (y / 32)) % 2 == 0;
        const bool emitter = std::hypot(x - 512.0f, y - 40.0f) < 30.0f;
        const float base[3] = {0.1f + 0.6f * u, 0.1f + 0.5f * v, 0.3f * (1.0f - u)};
        for (int c = 0; c < 3; ++c) {
          const float radiance = emitter ? 40.0f : base[c] * (tile ? 1.0f : 0.6f);
          reference_.pixel(x, y)[c] = radiance;
          test_.pixel(x, y)[c] = radiance * (0.6f + 0.8f * hashNoise(x, y, c));
        }
      }
  }

 protected:
  image::Image reference_;
  image::Image test_;
};

BENCHMARK_DEFINE_F(FlipFixture, Ldr1024x768)(benchmark::State& state) {
  for (auto _ : state) {
    const FlipResult result = computeLdrFlip(reference_, test_);
    benchmark::DoNotOptimize(result.mean);
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * kWidth_px * kHeight_px);
}
// Real time: the work runs on TBB worker threads, which the main thread's CPU time misses.
BENCHMARK_REGISTER_F(FlipFixture, Ldr1024x768)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_DEFINE_F(FlipFixture, Hdr1024x768)(benchmark::State& state) {
  int exposures = 0;
  for (auto _ : state) {
    const FlipResult result = computeHdrFlip(reference_, test_);
    exposures = result.exposure_count;
    benchmark::DoNotOptimize(result.mean);
  }
  state.counters["exposures"] = exposures;
  state.SetItemsProcessed(std::int64_t(state.iterations()) * kWidth_px * kHeight_px);
}
BENCHMARK_REGISTER_F(FlipFixture, Hdr1024x768)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace gib::metrics
