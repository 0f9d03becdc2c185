// Frame time and per-pass times of `direct` on the Cornell box at 512² (issue: "frame time and
// per-pass times"). Each iteration is one frame finished on the GPU (glFinish), timed by wall
// clock; the pass profiler's medians come out as counters "<pass>_ms" in its reported clock
// (CPU around glFinish on llvmpipe, GPU timestamps on a GPU).
#include "metrics/pass_timing_summary.h"
#include "realtime/gl/context.h"
#include "realtime/gl/gl.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gpu_scene.h"
#include "realtime/render_target.h"
#include "realtime/technique.h"
#include "scene/builtin_scenes.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <memory>

namespace gib::rt {
namespace {

gl::Context& benchContext() {
  static std::unique_ptr<gl::Context> context = gl::Context::create();
  return *context;
}

void BM_DirectFrame(benchmark::State& state, std::vector<std::string> set) {
  gl::Context& context = benchContext();
  context.makeCurrent();
  const scene::Scene scene = scene::loadScene("cornell", {});
  const int size = 512;
  const TechniqueInfo& info = findTechnique("direct");
  std::unique_ptr<Technique> technique =
      info.create(parseParameters(info.parameters, set, "technique 'direct'"));
  GpuScene gpu_scene(scene, size, size);
  technique->prepare(gpu_scene, size, size);
  RenderTarget target(size, size);
  gl::PassProfiler profiler(context.identity().software);
  Frame frame{target, profiler};
  for (int i = 0; i < 2; ++i) {  // warm-up: shader compilation on first use, caches
    profiler.beginFrame(false);
    technique->render(frame);
    profiler.endFrame();
  }
  for (auto _ : state) {
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    profiler.beginFrame(true);
    target.clear(0, 0, 0);
    technique->render(frame);
    profiler.endFrame();
    glFinish();
    state.SetIterationTime(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  const ProfileRecord record = profiler.finish();
  for (const metrics::PassTimingRow& row : metrics::summarizeProfile(record))
    state.counters[row.name + "_ms"] = row.reported.median;
  state.SetLabel(context.identity().renderer + ", " + record.reported_clock + " clock");
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
