// What the checked GL state costs on the CPU: entering and leaving a PipelineScope (depth test and
// additive blending, then back to the default state) against the raw glEnable/glDisable calls it
// replaced, and setting a uniform by name through Program::set (looked up and type-checked every
// call) against glProgramUniform with a location looked up once. Driver work only: nothing is
// drawn, so the difference is the wrappers' own cost per pass.
#include "realtime/gl/context.h"
#include "realtime/gl/fullscreen_pass.h"
#include "realtime/gl/gl.h"
#include "realtime/gl/pipeline_state.h"

#include <benchmark/benchmark.h>

#include <glm/gtc/type_ptr.hpp>
#include <glm/vec3.hpp>

namespace {

using namespace gib;

rt::gl::Context& glContext() {
  // Leaked on purpose, as in the tests: destroying a context after main() races the driver.
  static rt::gl::Context* context = rt::gl::Context::create().release();
  return *context;
}

void BM_RawStateCalls(benchmark::State& state) {
  glContext();
  for (auto _ : state) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
  }
  glFinish();
}
BENCHMARK(BM_RawStateCalls);

void BM_PipelineScope(benchmark::State& state) {
  glContext();
  const rt::gl::PipelineState lit{.depth_test = GL_LEQUAL, .blend = rt::gl::kAdditiveBlend};
  for (auto _ : state) {
    const rt::gl::PipelineScope scope(lit);
    benchmark::DoNotOptimize(&scope);
  }
  glFinish();
}
BENCHMARK(BM_PipelineScope);

void BM_UniformByLocation(benchmark::State& state) {
  glContext();
  const rt::gl::FullScreenPass pass("realtime/lighting/emission.frag.glsl");
  const GLuint program = pass.program().id();
  const GLint location = glGetUniformLocation(program, "u_sky_radiance");
  const glm::vec3 value(0.1f, 0.2f, 0.3f);
  for (auto _ : state) glProgramUniform3fv(program, location, 1, glm::value_ptr(value));
  glFinish();
}
BENCHMARK(BM_UniformByLocation);

void BM_UniformByCheckedName(benchmark::State& state) {
  glContext();
  const rt::gl::FullScreenPass pass("realtime/lighting/emission.frag.glsl");
  const glm::vec3 value(0.1f, 0.2f, 0.3f);
  for (auto _ : state) pass.program().set("u_sky_radiance", value);
  glFinish();
}
BENCHMARK(BM_UniformByCheckedName);

}  // namespace
