// `gpu_ray_tracing` (book Ch. 5, Figs. 5.7 and 5.15: reflective and refractive objects at 512²,
// 10 FPS on a GeForce 6800): a frame on the Cornell box with a mirror and a glass sphere at the
// book's 512², through the BVH and the loose kd-tree at the default depth 4, and through the BVH
// at depth 1 (the mirror's reflection alone, the glass's first reflection only), so the trace's
// share of the frame reads against the tree's depth. Brute force is left out: 33 000 triangles
// per ray at 512² take minutes a frame on llvmpipe. See support/technique_frames.h for what is
// timed and reported.
#include "support/technique_frames.h"

namespace gib::rt {
namespace {

void BM_GpuRayTracingFrame(benchmark::State& state, std::vector<std::string> set) {
  benchmarkTechniqueFrames(state, "gpu_ray_tracing", set, "cornell", 512, 0, {},
                           {"spheres=mirror_glass"});
}

BENCHMARK_CAPTURE(BM_GpuRayTracingFrame, bvh_depth4, std::vector<std::string>{"structure=bvh"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GpuRayTracingFrame, loose_kd_tree_depth4,
                  std::vector<std::string>{"structure=loose_kd_tree"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GpuRayTracingFrame, bvh_depth1,
                  std::vector<std::string>{"structure=bvh", "max_depth=1"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gib::rt
