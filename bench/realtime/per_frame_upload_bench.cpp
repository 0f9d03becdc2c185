// Per-frame data written for the draws that read it: glBufferSubData into one buffer (what the
// shadow batches and probe views did) against a persistently mapped ring (gl::StreamBuffer).
// One iteration is a frame of state.range(0) rounds, each a 16 KiB uniform block written and
// then read by a fullscreen triangle on a 64×64 float target, ended by glFinish. Rewriting a
// buffer that a queued draw still reads makes a driver copy or wait; the ring writes elsewhere.
#include "realtime/gl/context.h"
#include "realtime/gl/gl.h"
#include "realtime/gl/objects.h"
#include "realtime/gl/shader_library.h"
#include "realtime/gl/stream_buffer.h"

#include <benchmark/benchmark.h>
#include <glm/vec4.hpp>

#include <string_view>
#include <vector>

namespace {

using namespace gib;

rt::gl::Context& glContext() {
  // Leaked on purpose, as in the tests: destroying a context after main() races the driver.
  static rt::gl::Context* context = rt::gl::Context::create().release();
  return *context;
}

constexpr int kSize = 64;
constexpr std::size_t kValues = 1024;  // 16 KiB of vec4
constexpr std::size_t kBlockBytes = kValues * sizeof(glm::vec4);

std::string_view source(std::string_view path) {
  if (path == "bench/fullscreen.vert.glsl")
    return "void main() {\n"
           "  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
           "  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n"
           "}\n";
  return "layout(std140, binding = 0) uniform Block { vec4 u_values[1024]; };\n"
         "layout(location = 0) out vec4 color;\n"
         "void main() { color = u_values[int(gl_FragCoord.y) * 16 + int(gl_FragCoord.x) % 16]; }\n";
}

enum class Upload { kSubData, kStream };

void BM_PerFrameUpload(benchmark::State& state, Upload upload) {
  glContext().makeCurrent();
  const rt::gl::Texture texture = rt::gl::Texture::make2D(GL_RGBA32F, kSize, kSize);
  rt::gl::Framebuffer framebuffer;
  framebuffer.attachColor(0, texture);
  framebuffer.setDrawBuffers(1);
  framebuffer.checkComplete();
  const rt::gl::VertexArray vertex_array;
  const rt::gl::Program program =
      rt::gl::buildProgram({{GL_VERTEX_SHADER, "bench/fullscreen.vert.glsl"},
                            {GL_FRAGMENT_SHADER, "bench/block.frag.glsl"}},
                           "", source);
  rt::gl::Buffer buffer(kBlockBytes, nullptr);
  rt::gl::StreamBuffer stream;
  std::vector<glm::vec4> values(kValues);
  const auto rounds = int(state.range(0));
  framebuffer.bind();
  glViewport(0, 0, kSize, kSize);
  program.use();
  vertex_array.bind();
  float frame = 0;
  for (auto _ : state) {
    for (int r = 0; r < rounds; ++r) {
      for (std::size_t i = 0; i < kValues; ++i) values[i] = glm::vec4(frame, float(r), float(i), 1);
      if (upload == Upload::kSubData) {
        buffer.update(0, kBlockBytes, values.data());
        buffer.bindBase(GL_UNIFORM_BUFFER, 0);
      } else {
        stream.beginRound({kBlockBytes});
        stream.bindRange(GL_UNIFORM_BUFFER, 0, stream.push(values), kBlockBytes);
      }
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glFinish();
    frame += 1;
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * rounds);
}
BENCHMARK_CAPTURE(BM_PerFrameUpload, subdata, Upload::kSubData)->Arg(1)->Arg(32);
BENCHMARK_CAPTURE(BM_PerFrameUpload, stream, Upload::kStream)->Arg(1)->Arg(32);

}  // namespace
