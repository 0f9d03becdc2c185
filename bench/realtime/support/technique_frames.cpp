#include "support/technique_frames.h"

#include "metrics/pass_timing_summary.h"
#include "realtime/gl/context.h"
#include "realtime/gl/finished_time.h"
#include "realtime/gl/gl.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/render_target.h"
#include "realtime/technique.h"
#include "scene/builtin_scenes.h"

#include <memory>

namespace gib::rt {

namespace {

gl::Context& benchContext() {
  static std::unique_ptr<gl::Context> context = gl::Context::create();
  return *context;
}

void reportPasses(benchmark::State& state, gl::PassProfiler& profiler, gl::Context& context) {
  const ProfileRecord record = profiler.finish();
  const metrics::PassTimings timings = metrics::summarizeProfile(record);
  for (const metrics::PassTiming& row : timings.passes)
    state.counters[row.path + "_ms"] = row.reported.median;
  // The draws and dispatches of a frame: what a real GPU's per-command overhead scales with.
  if (timings.root().gpu_commands_per_frame)
    state.counters[timings.root().path + "_gpu_commands"] = *timings.root().gpu_commands_per_frame;
  state.SetLabel(context.identity().renderer + ", " + record.reported_clock + " clock");
}

std::unique_ptr<Technique> createTechnique(const std::string& name,
                                           const std::vector<std::string>& set) {
  const TechniqueInfo& info = findTechnique(name);
  return info.create(parseParameters(info.parameters, set, "technique '" + name + "'"));
}

}  // namespace

void benchmarkTechniqueIterations(benchmark::State& state, const std::string& technique_name,
                                  const std::vector<std::string>& set,
                                  const std::string& scene_name, int warmup_iterations,
                                  const std::vector<std::string>& scene_set) {
  gl::Context& context = benchContext();
  context.makeCurrent();
  const scene::Scene scene = scene::loadScene(scene_name, scene_set);
  std::unique_ptr<Technique> technique = createTechnique(technique_name, set);
  GpuScene gpu_scene(scene, 64, 64);  // the camera image is not drawn
  technique->prepare(gpu_scene, 64, 64);
  gl::PassProfiler profiler(context.identity().software, 4, "iteration");  // as the runner names it
  for (int i = 0; i < warmup_iterations; ++i) technique->step(profiler);
  for (auto _ : state)
    state.SetIterationTime(1e-3 * gl::finishedMilliseconds([&] {
                             profiler.beginFrame(true);
                             technique->step(profiler);
                             profiler.endFrame();
                           }));
  reportPasses(state, profiler, context);
}

void benchmarkTechniqueFrames(benchmark::State& state, const std::string& technique_name,
                              const std::vector<std::string>& set, const std::string& scene_name,
                              int size, int width, const TechniqueServices& services,
                              const std::vector<std::string>& scene_set) {
  gl::Context& context = benchContext();
  context.makeCurrent();
  const scene::Scene scene = scene::loadScene(scene_name, scene_set);
  // The needs the runner checks, checked here too: the benchmark makes the technique itself.
  if (const std::optional<std::string> missing =
          missingNeed(findTechnique(technique_name), scene, services)) {
    state.SkipWithError(missing->c_str());
    return;
  }
  std::unique_ptr<Technique> technique = createTechnique(technique_name, set);
  const int w = width > 0 ? width : size;
  GpuScene gpu_scene(scene, w, size);
  technique->provide(services);
  technique->prepare(gpu_scene, w, size);
  RenderTarget target(w, size);
  gl::PassProfiler profiler(context.identity().software || technique->timedOnCpu());
  // An endless run: an animating technique keeps animating (frames_left never reaches 0).
  Frame frame{target, profiler, 1 << 30, 1 << 30};
  for (int i = 0; i < 2; ++i) {  // warm-up: shader compilation on first use, caches
    profiler.beginFrame(false);
    technique->render(frame);
    profiler.endFrame();
  }
  for (auto _ : state)
    state.SetIterationTime(1e-3 * gl::finishedMilliseconds([&] {
                             profiler.beginFrame(true);
                             target.clear(0, 0, 0);
                             technique->render(frame);
                             profiler.endFrame();
                           }));
  reportPasses(state, profiler, context);
  // The technique's own counts and timings (records, texels, preparation phases).
  for (const TechniqueStatistic& s : technique->statistics()) state.counters[s.name] = s.value;
}

}  // namespace gib::rt
