// Time per iteration of `stochastic_radiosity` on the Cornell box and per pass (selection,
// visibility, update, mipmap), at the book's 128² atlas and the paper's 512², for both selection
// variants (issue 7: "time per iteration and per pass at 128² and 512²"); see
// support/technique_frames.h for what is timed and reported.
#include "support/technique_frames.h"

namespace gib::rt {
namespace {

// Enough warm-up iterations that the estimate, and so the shooters chosen, are past the first
// bounces: an iteration's cost does not depend on which texel shoots, but caches do warm up.
constexpr int kWarmupIterations = 10;

void BM_StochasticRadiosityIteration(benchmark::State& state, std::vector<std::string> set) {
  benchmarkTechniqueIterations(state, "stochastic_radiosity", set, "cornell", kWarmupIterations);
}

BENCHMARK_CAPTURE(BM_StochasticRadiosityIteration, atlas128_gpu,
                  std::vector<std::string>{"atlas=128", "selection=gpu"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StochasticRadiosityIteration, atlas128_cpu,
                  std::vector<std::string>{"atlas=128", "selection=cpu"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StochasticRadiosityIteration, atlas512_gpu,
                  std::vector<std::string>{"atlas=512", "selection=gpu"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StochasticRadiosityIteration, atlas512_cpu,
                  std::vector<std::string>{"atlas=512", "selection=cpu"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StochasticRadiosityIteration, atlas512_hemisphere_gpu,
                  std::vector<std::string>{"atlas=512", "selection=gpu", "projection=hemisphere"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gib::rt
