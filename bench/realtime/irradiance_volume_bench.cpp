// Frame and per-pass times of `irradiance_volume` at the paper's settings (4³ grid, 16² faces,
// 9 coefficients, 2 iterations; Nijasure et al. 2005, Table 1) at 512², on the Cornell box and
// the chamber (the paper's Hall), with the cube maps rasterised every frame (moving objects) or
// once (moving light), and at larger settings. Counters: each pass's median, by path.
#include "support/technique_frames.h"

namespace gib::rt {
namespace {

void BM_IrradianceVolumeFrame(benchmark::State& state, std::string scene,
                              std::vector<std::string> set) {
  set.push_back("light_samples=16");
  benchmarkTechniqueFrames(state, "irradiance_volume", set, scene, 512);
}

BENCHMARK_CAPTURE(BM_IrradianceVolumeFrame, cornell_paper_objects, "cornell",
                  std::vector<std::string>{"motion=objects"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_IrradianceVolumeFrame, cornell_paper_light, "cornell",
                  std::vector<std::string>{"motion=light"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_IrradianceVolumeFrame, chamber_paper_objects, "chamber",
                  std::vector<std::string>{"motion=objects"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_IrradianceVolumeFrame, chamber_paper_light, "chamber",
                  std::vector<std::string>{"motion=light"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_IrradianceVolumeFrame, cornell_grid8_face32_shadows, "cornell",
                  std::vector<std::string>{"grid=8", "face=32", "indirect_shadows=on"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gib::rt
