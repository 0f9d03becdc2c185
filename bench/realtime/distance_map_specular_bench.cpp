// `distance_map_specular` (book §6.1-6.3, Figs. 6.9 and 6.11: 130 and 440 FPS for a glass skull
// and an aluminium teapot in a box, and the artefacts of 15/1, 15/10, 80/1 and 80/10 linear/secant
// steps): a frame on the Cornell box with a mirror and a glass sphere at 1024 × 768, the maps at
// the games' 6 × 256² (§6.8), at each of the book's four step counts. The counters split the
// frame: the maps' update (`frame/map views_ms`, `frame/lights/map light_ms`,
// `frame/compose maps_ms`) does not depend on the steps; the search per pixel is
// `frame/specular_ms` (every mirror and glass pixel's rays searched in its object's map). See
// support/technique_frames.h for what is timed and reported.
#include "reference/embree_scene.h"
#include "support/technique_frames.h"

namespace gib::rt {
namespace {

void BM_DistanceMapSpecularFrame(benchmark::State& state, std::vector<std::string> set) {
  // Embree lent as the harness lends it (the search_error image's rays; no frame casts any).
  benchmarkTechniqueFrames(state, "distance_map_specular", set, "cornell", 768, 1024,
                           {ref::embreeRayCasterFactory()}, {"spheres=mirror_glass"});
}

BENCHMARK_CAPTURE(BM_DistanceMapSpecularFrame, steps_15_1,
                  std::vector<std::string>{"linear_steps=15", "secant_steps=1"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DistanceMapSpecularFrame, steps_15_10,
                  std::vector<std::string>{"linear_steps=15", "secant_steps=10"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DistanceMapSpecularFrame, steps_80_1,
                  std::vector<std::string>{"linear_steps=80", "secant_steps=1"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DistanceMapSpecularFrame, steps_80_10,
                  std::vector<std::string>{"linear_steps=80", "secant_steps=10"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
// Environment mapping: the specular pass without a search, the floor of its cost.
BENCHMARK_CAPTURE(BM_DistanceMapSpecularFrame, environment,
                  std::vector<std::string>{"search=environment"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gib::rt
