// Frame time and per-pass times of `direct` on the Cornell box at 512² (issue: "frame time and
// per-pass times"); see support/technique_frames.h for what is timed and reported.
#include "support/technique_frames.h"

namespace gib::rt {
namespace {

void BM_DirectFrame(benchmark::State& state, std::vector<std::string> set) {
  benchmarkTechniqueFrames(state, "direct", set, "cornell", 512);
}

BENCHMARK_CAPTURE(BM_DirectFrame, hard_1,
                  std::vector<std::string>{"shadow=hard", "light_samples=1"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DirectFrame, hard_16, std::vector<std::string>{"shadow=hard"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DirectFrame, pcf_16, std::vector<std::string>{"shadow=pcf"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_DirectFrame, vsm_16, std::vector<std::string>{"shadow=vsm"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gib::rt
