// One gathered bounce (Fournier & Péroche §5) on the Cornell box at 64², a gather point every 8
// pixels (64 views a frame): each projection's frame, with its passes as counters (views, slices,
// sums, interpolation).
#include "support/technique_frames.h"

#include <benchmark/benchmark.h>

#include <string>

namespace {

void BM_HemisphericalGatherFrame(benchmark::State& state, const char* projection) {
  gib::rt::benchmarkTechniqueFrames(state, "hemispherical_gather",
                                    {std::string("projection=") + projection}, "cornell", 64);
}
BENCHMARK_CAPTURE(BM_HemisphericalGatherFrame, perspective, "perspective")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_HemisphericalGatherFrame, hemispherical, "hemispherical")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_HemisphericalGatherFrame, voxel_slices, "voxel_slices")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
