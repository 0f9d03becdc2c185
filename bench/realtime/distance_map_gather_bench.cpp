// `distance_map_gather` (book §7.3, Figs. 7.10-7.13): a frame on the room (scene/room.cpp, the
// book's room of fire balls) at 1024 × 768 with the sphere, gathering from the book's 6 × 256² map
// downsampled to M = 2 and 4 (the book's two resolutions), M = 4 with a shadow ray per texel
// (visibility=true, not the book's), and the classic irradiance map from the same map; the counters
// "frame/gather_ms", "frame/downsample_ms", "frame/map views_ms", "frame/lights/map light_ms" and
// "frame/compose maps_ms" split the frame into the gather per pixel and the map's update. See
// support/technique_frames.h for what is timed and reported.
#include "support/technique_frames.h"

namespace gib::rt {
namespace {

void BM_DistanceMapGatherFrame(benchmark::State& state, std::vector<std::string> set) {
  benchmarkTechniqueFrames(state, "distance_map_gather", set, "room", 768, 1024);
}

BENCHMARK_CAPTURE(BM_DistanceMapGatherFrame, distance_map_m2,
                  std::vector<std::string>{"gather_resolution=2"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DistanceMapGatherFrame, distance_map_m4,
                  std::vector<std::string>{"gather_resolution=4"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DistanceMapGatherFrame, distance_map_m4_visibility,
                  std::vector<std::string>{"gather_resolution=4", "visibility=true"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DistanceMapGatherFrame, irradiance_map,
                  std::vector<std::string>{"mode=irradiance_map"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gib::rt
