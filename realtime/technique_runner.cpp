#include "realtime/technique_runner.h"

#include "common/environment_error.h"
#include "common/input_error.h"
#include "realtime/gbuffer/gbuffer.h"
#include "realtime/gl/finished_time.h"
#include "realtime/gl/gl.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/render_target.h"

#include <fmt/format.h>

#include <stdexcept>

namespace gib::rt {

namespace {

void checkSettings(const TechniqueRunSettings& s) {
  constexpr int kMaxSize = 16384;
  if (s.width < 1 || s.height < 1 || s.width > kMaxSize || s.height > kMaxSize)
    throw InputError(fmt::format("image size {}x{} is out of range; give 1 to {} per side", s.width,
                                 s.height, kMaxSize));
  if (s.frames < 1)
    throw InputError(fmt::format("--frames {} measures nothing; give at least 1", s.frames));
  if (s.warmup_frames < 0)
    throw InputError(fmt::format("--warmup {} is negative; give 0 or more", s.warmup_frames));
  if (s.iterations < 0)
    throw InputError(fmt::format("--iterations {} is negative; give 0 or more", s.iterations));
  int previous = 0;
  for (int count : s.capture_after) {
    if (count < previous || count > s.iterations)
      throw InputError(fmt::format(
          "iteration checkpoint {} is out of order or beyond the {} iterations run; give "
          "ascending counts up to the iteration count",
          count, s.iterations));
    previous = count;
  }
}

// Runs the iterations, each step() one profiled "iteration", capturing the image after the
// requested counts. A capture renders outside any profiled frame, so it is not timed.
void iterate(Technique& technique, const TechniqueRunSettings& settings, bool precise,
             RenderTarget& target, TechniqueRunResult& result) {
  gl::PassProfiler profiler(precise, 4, kIterationPass);
  gl::PassProfiler untimed(precise);
  Frame capture_frame{target, untimed};
  std::size_t next_capture = 0;
  auto capture = [&](int count) {
    for (; next_capture < settings.capture_after.size() &&
           settings.capture_after[next_capture] == count;
         ++next_capture) {
      target.clear(0, 0, 0);
      technique.render(capture_frame);
      result.captures.push_back({count, result.iterate_ms, target.read()});
    }
  };
  capture(0);
  for (int i = 1; i <= settings.iterations; ++i) {
    result.iterate_ms += gl::finishedMilliseconds([&] {
      profiler.beginFrame(true);
      technique.step(profiler);
      profiler.endFrame();
    });
    capture(i);
  }
  result.iteration_profile = profiler.finish();
  result.iterations = technique.iterations();
}

// A pass the technique does not declare would be invisible to suites and to the declared list the
// README shows: a bug in the technique, found by every test that runs it.
void checkDeclared(const TechniqueInfo& info, const ProfileRecord& record) {
  for (const PassRecord& pass : record.passes)
    if (!info.passes.declares(pass.path))
      throw std::logic_error(fmt::format(
          "technique '{}' timed the pass '{}', which its TechniqueInfo::passes does not declare",
          info.name, pass.path));
}

// An image or a statistic the technique does not declare would reach a report that no suite could
// name and no README lists: a bug in the technique, found by every test that runs it.
template <typename Output>
void checkOutputsDeclared(const TechniqueInfo& info, const std::vector<Output>& outputs,
                          const std::vector<DeclaredOutput>& declared, std::string_view what,
                          std::string_view field) {
  for (const Output& output : outputs)
    if (!findDeclaredOutput(declared, output.name))
      throw std::logic_error(fmt::format(
          "technique '{}' wrote the {} '{}', which its TechniqueInfo::{} does not declare",
          info.name, what, output.name, field));
}

// One line for the command line and a suite's failure record: a shader's log (several lines)
// gives its first error; the rest is there for a developer who runs the technique's test.
std::string oneLineSummary(const std::string& message) {
  const std::size_t first = message.find('\n');
  if (first == std::string::npos) return message;
  const std::size_t second = message.find('\n', first + 1);
  std::string line = message.substr(0, first);
  if (!line.empty() && line.back() == ':') line.pop_back();
  return line + ": " +
         message.substr(first + 1,
                        second == std::string::npos ? std::string::npos : second - first - 1);
}

// The run itself; runTechnique names the technique in its environment errors.
TechniqueRunResult runTechniqueUnnamed(const scene::Scene& scene, const TechniqueInfo& info,
                                       const ParameterValues& parameters,
                                       const TechniqueRunSettings& settings) {
  checkSettings(settings);
  if (const std::optional<std::string> missing = missingNeed(info, scene, settings.services))
    throw InputError(*missing);
  std::unique_ptr<gl::Context> context = gl::Context::create(settings.context);
  TechniqueRunResult result;
  result.gl = context->identity();
  {
    std::unique_ptr<Technique> technique = info.create(parameters);
    std::optional<GpuScene> gpu_scene;
    result.upload_ms = gl::finishedMilliseconds(
        [&] { gpu_scene.emplace(scene, settings.width, settings.height); });
    technique->provide(settings.services);
    result.prepare_ms = gl::finishedMilliseconds(
        [&] { technique->prepare(*gpu_scene, settings.width, settings.height); });
    result.statistics = technique->statistics();
    checkOutputsDeclared(info, result.statistics, info.statistics, "statistic", "statistics");
    const bool precise = technique->timedOnCpu() || settings.precise.value_or(result.gl.software);
    RenderTarget target(settings.width, settings.height);
    if (technique->iterative()) iterate(*technique, settings, precise, target, result);
    gl::PassProfiler profiler(precise);
    const int frame_count = settings.warmup_frames + settings.frames;
    Frame frame{target, profiler, 0, frame_count};
    for (int i = 0; i < frame_count; ++i) {
      frame.frames_left = frame_count - 1 - i;
      profiler.beginFrame(i >= settings.warmup_frames);
      target.clear(0, 0, 0);
      technique->render(frame);
      profiler.endFrame();
    }
    result.profile = profiler.finish();
    checkDeclared(info, result.profile);
    checkDeclared(info, result.iteration_profile);
    result.image = target.read();
    result.auxiliary = technique->auxiliaryImages();
    checkOutputsDeclared(info, result.auxiliary, info.auxiliary_images, "auxiliary image",
                         "auxiliary_images");
    const std::vector<TechniqueStatistic> measured = technique->finalStatistics();
    checkOutputsDeclared(info, measured, info.statistics, "statistic", "statistics");
    result.statistics.insert(result.statistics.end(), measured.begin(), measured.end());
    result.region = technique->measuredRegion();
    result.path_class = technique->pathClass();
    result.obscurance = technique->imageObscurance();
    if (settings.capture_primary_surfaces) {
      GBuffer gbuffer(settings.width, settings.height);
      gbuffer.render(*gpu_scene);
      result.primary = PrimarySurfaces{gl::readTexture(gbuffer.position(), 4),
                                       gl::readTexture(gbuffer.normal(), 4)};
    }
  }
  if (context->debug()) {
    const std::vector<std::string> errors = context->takeDebugErrors();
    if (!errors.empty())
      throw std::runtime_error(fmt::format("technique '{}' caused {} GL error(s); first: {}",
                                           info.name, errors.size(), errors.front()));
  }
  return result;
}

}  // namespace

TechniqueRunResult runTechnique(const scene::Scene& scene, const TechniqueInfo& info,
                                const ParameterValues& parameters,
                                const TechniqueRunSettings& settings) {
  try {
    return runTechniqueUnnamed(scene, info, parameters, settings);
  } catch (const EnvironmentError& e) {
    throw EnvironmentError(fmt::format("technique '{}': {}", info.name, oneLineSummary(e.what())));
  }
}

std::map<std::string, std::string> techniqueRunMetadata(const TechniqueRunResult& r,
                                                        const TechniqueRunSettings& s) {
  std::map<std::string, std::string> m;
  m["gibench/gl_device"] = r.gl.device;
  m["gibench/gl_vendor"] = r.gl.vendor;
  m["gibench/gl_renderer"] = r.gl.renderer;
  m["gibench/gl_version"] = r.gl.version;
  m["gibench/warmup_frames"] = std::to_string(s.warmup_frames);
  m["gibench/frames"] = std::to_string(s.frames);
  m["gibench/timing_clock"] = r.profile.reported_clock == "cpu"
                                  ? "cpu (wall clock around glFinish per pass)"
                                  : "gpu (timestamp queries)";
  m["gibench/upload_ms"] = fmt::format("{:.3f}", r.upload_ms);
  m["gibench/prepare_ms"] = fmt::format("{:.3f}", r.prepare_ms);
  if (r.iterations > 0) {
    m["gibench/iterations"] = std::to_string(r.iterations);
    m["gibench/iterate_ms"] = fmt::format("{:.3f}", r.iterate_ms);
  }
  return m;
}

}  // namespace gib::rt
