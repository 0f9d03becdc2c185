// What profiling costs: frames of small passes (one fullscreen triangle on a 64×64 float target
// each) with no profiler, with timestamp queries, and in precise mode; and summarising a long
// profile.
#include "metrics/pass_timing_summary.h"
#include "realtime/gl/context.h"
#include "realtime/gl/gl.h"
#include "realtime/gl/objects.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/shader_library.h"

#include <benchmark/benchmark.h>

#include <optional>
#include <random>

namespace {

using namespace gib;
using rt::gl::PassProfiler;

rt::gl::Context& glContext() {
  // Leaked on purpose, as in the tests: destroying a context after main() races the driver.
  static rt::gl::Context* context = rt::gl::Context::create().release();
  return *context;
}

// A 64×64 float target and one fullscreen triangle of a constant colour: a pass the driver has
// to execute (consecutive clears it would merge into one, which a profiler's queries between
// them prevent, so clears would bill the profiler for work the unprofiled frame never did).
class SmallPass {
 public:
  SmallPass() {
    framebuffer_.attachColor(0, texture_);
    framebuffer_.setDrawBuffers(1);
    framebuffer_.checkComplete();
  }
  void run() const {
    framebuffer_.bind();
    glViewport(0, 0, kSize, kSize);
    program_.use();
    vertex_array_.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }

 private:
  static constexpr int kSize = 64;
  static std::string_view source(std::string_view path) {
    if (path == "bench/fullscreen.vert.glsl")
      return "void main() {\n"
             "  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
             "  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n"
             "}\n";
    return "layout(location = 0) out vec4 color;\nvoid main() { color = vec4(0.25); }\n";
  }
  rt::gl::Texture texture_ = rt::gl::Texture::make2D(GL_RGBA32F, kSize, kSize);
  rt::gl::Framebuffer framebuffer_;
  rt::gl::VertexArray vertex_array_;
  rt::gl::Program program_ =
      rt::gl::buildProgram({{GL_VERTEX_SHADER, "bench/fullscreen.vert.glsl"},
                            {GL_FRAGMENT_SHADER, "bench/constant.frag.glsl"}},
                           "", source);
};

enum class Profiling { kNone, kQueries, kPrecise };

// One iteration is a frame of state.range(0) passes, ended by glFinish as a present would
// throttle it, so that every variant waits for the same GPU work.
void BM_ProfiledFrame(benchmark::State& state, Profiling profiling) {
  glContext().makeCurrent();
  const SmallPass work;
  std::optional<PassProfiler> profiler;
  if (profiling != Profiling::kNone) profiler.emplace(profiling == Profiling::kPrecise);
  const auto passes = int(state.range(0));
  for (auto _ : state) {
    if (profiler) profiler->beginFrame();
    for (int p = 0; p < passes; ++p) {
      std::optional<PassProfiler::Scope> scope;
      if (profiler) scope.emplace(profiler->pass("draw"));
      work.run();
    }
    if (profiler) profiler->endFrame();
    glFinish();
  }
  if (profiler) benchmark::DoNotOptimize(profiler->finish().measured_frames);
  state.SetItemsProcessed(std::int64_t(state.iterations()) * passes);
}
BENCHMARK_CAPTURE(BM_ProfiledFrame, unprofiled, Profiling::kNone)->Arg(1)->Arg(10);
BENCHMARK_CAPTURE(BM_ProfiledFrame, timestamp_queries, Profiling::kQueries)->Arg(1)->Arg(10);
BENCHMARK_CAPTURE(BM_ProfiledFrame, precise, Profiling::kPrecise)->Arg(1)->Arg(10);

// 1000 measured frames of ten passes (the frame, three top-level passes, six nested), both clocks.
rt::ProfileRecord syntheticProfile() {
  constexpr int kFrames = 1000;
  rt::ProfileRecord record;
  record.reported_clock = "cpu";
  record.precise = true;
  record.measured_frames = kFrames;
  std::mt19937 random(7);
  std::lognormal_distribution<double> ms(0.0, 0.3);
  const char* paths[] = {"frame",     "frame/a",   "frame/a/x", "frame/a/y", "frame/b",
                         "frame/b/x", "frame/b/y", "frame/c",   "frame/c/x", "frame/c/y"};
  for (const char* path : paths) {
    const std::string p = path;
    rt::PassRecord pass{
        p.substr(p.rfind('/') + 1),   p, int(std::count(p.begin(), p.end(), '/')), {}, {},
        std::vector<int>(kFrames, 1), {}};
    for (int f = 0; f < kFrames; ++f) {
      pass.gpu_ms.push_back(ms(random));
      pass.cpu_ms.push_back(ms(random));
    }
    record.passes.push_back(std::move(pass));
  }
  return record;
}

void BM_ProfileSummary(benchmark::State& state) {
  const rt::ProfileRecord record = syntheticProfile();
  for (auto _ : state) benchmark::DoNotOptimize(metrics::summarizeProfile(record));
}
BENCHMARK(BM_ProfileSummary)->Unit(benchmark::kMillisecond);

}  // namespace
