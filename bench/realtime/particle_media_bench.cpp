// The cloud in real time (book Ch. 9), per pass at 512² on the `cloud` scene: a
// `spherical_billboards` frame (volume shadow, particle shading, sorting, billboards), an
// `illumination_network` frame (shading, sorting, billboards) and one network iteration
// (scattering, transport), against the particle count (256…4096, the book's 1024), the network's
// direction count (32…256, the book's 128) and the number of lights (1, 2, 4; without the sky).
// The network's preparation (visibility network, emission) is reported as counters
// prepare_visibility_ms and prepare_emission_ms; BM_IlluminationNetworkFrame1024x768 is the frame
// the issue sets a GPU target for.
#include "support/technique_frames.h"

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace {

std::vector<std::string> cloudSet(const benchmark::State& state) {
  return {"particles=" + std::to_string(state.range(0)), "lights=" + std::to_string(state.range(2)),
          std::string("sky=") + (state.range(3) ? "true" : "false")};
}

void BM_SphericalBillboardsFrame(benchmark::State& state) {
  gib::rt::benchmarkTechniqueFrames(state, "spherical_billboards", {}, "cloud", 512, 0, {},
                                    cloudSet(state));
}

void BM_IlluminationNetworkFrame(benchmark::State& state) {
  gib::rt::benchmarkTechniqueFrames(state, "illumination_network",
                                    {"directions=" + std::to_string(state.range(1))}, "cloud", 512,
                                    0, {}, cloudSet(state));
}

void BM_IlluminationNetworkIteration(benchmark::State& state) {
  gib::rt::benchmarkTechniqueIterations(state, "illumination_network",
                                        {"directions=" + std::to_string(state.range(1))}, "cloud",
                                        1, cloudSet(state));
}

// Arguments: particles, directions, lights, sky.
void particleArguments(benchmark::internal::Benchmark* b) {
  b->ArgNames({"particles", "directions", "lights", "sky"});
  for (int particles : {256, 1024, 4096}) b->Args({particles, 128, 2, 1});
  for (int directions : {32, 256}) b->Args({1024, directions, 2, 1});
  for (int lights : {1, 4}) b->Args({1024, 128, lights, 1});
  b->Args({1024, 128, 2, 0});
}

BENCHMARK(BM_SphericalBillboardsFrame)
    ->Args({256, 128, 2, 1})
    ->Args({1024, 128, 2, 1})
    ->Args({4096, 128, 2, 1})
    ->Args({1024, 128, 1, 1})
    ->Args({1024, 128, 4, 1})
    ->Args({1024, 128, 2, 0})
    ->ArgNames({"particles", "directions", "lights", "sky"})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime();
BENCHMARK(BM_IlluminationNetworkFrame)
    ->Apply(particleArguments)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime();
BENCHMARK(BM_IlluminationNetworkIteration)
    ->Apply(particleArguments)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime();

// The GPU target for the network: a 1024×768 frame at the book's settings (1024
// particles, 128 directions, two lights and the sky).
void BM_IlluminationNetworkFrame1024x768(benchmark::State& state) {
  gib::rt::benchmarkTechniqueFrames(state, "illumination_network", {}, "cloud", 768, 1024);
}
BENCHMARK(BM_IlluminationNetworkFrame1024x768)->Unit(benchmark::kMillisecond)->UseManualTime();

}  // namespace
