// Per-frame data goes through persistently mapped rings (realtime/gl/stream_buffer.h): what a
// round pushes is what the GPU reads from the range bound, in every region of the ring, after
// it grows, and while earlier draws are still queued; a push beyond its round is refused.
#include "realtime/gl/stream_buffer.h"

#include "realtime/gl/pipeline_state.h"
#include "realtime/gl/shader_library.h"
#include "support/gl_test_context.h"
#include "support/glsl_sources.h"

#include <gtest/gtest.h>
#include <glm/vec4.hpp>

#include <stdexcept>
#include <vector>

namespace gib::rt::gl {
namespace {

// Copies the uniform block bound at binding 0 (16 uvec4) into the storage buffer at binding 1.
Program copyProgram() {
  return buildProgram({{GL_COMPUTE_SHADER, "copy.comp.glsl"}}, "",
                      test::glslSources({{"copy.comp.glsl", R"(
layout(local_size_x = 16) in;
layout(std140, binding = 0) uniform Block { uvec4 u_values[16]; };
layout(std430, binding = 1) buffer Out { uvec4 o_values[]; };
void main() { o_values[gl_GlobalInvocationID.x] = u_values[gl_GlobalInvocationID.x]; }
)"}}));
}

std::vector<glm::uvec4> roundValues(int round, std::size_t count) {
  std::vector<glm::uvec4> values;
  for (std::size_t i = 0; i < count; ++i)
    values.push_back(glm::uvec4(unsigned(round), unsigned(i), unsigned(round * 1000 + int(i)), 7u));
  return values;
}

class StreamBufferTest : public test::GlTest {};

// Seven rounds, each 100 KiB of padding and a block the GPU copies out right after it is pushed:
// two rounds to a region of the first ring, so rounds move on through its regions; the fourth
// round asks for more than a region and gets a ring of larger regions. Every round's copy holds
// its own values, and each push starts at an aligned offset inside the region its round took.
TEST_F(StreamBufferTest, TheGpuReadsWhatEachRoundPushedThroughTheRing) {
  const Program copy = copyProgram();
  constexpr std::size_t kBlock = 16 * sizeof(glm::uvec4);
  constexpr int kRounds = 7;
  Buffer out(kRounds * kBlock, nullptr);
  StreamBuffer stream;
  std::size_t first_region_bytes = 0;
  for (int round = 0; round < kRounds; ++round) {
    const std::size_t padding = round == 3 ? StreamBuffer::kMinRegionBytes : 100u << 10;
    stream.beginRound({padding, kBlock});
    if (round == 0) first_region_bytes = stream.regionBytes();
    const std::vector<char> filler(padding, char(round));
    const std::size_t filler_offset = stream.push(filler.data(), filler.size());
    const std::size_t offset = stream.push(roundValues(round, 16));
    ASSERT_EQ(offset % stream.alignment(), 0u);
    ASSERT_GE(offset, filler_offset + padding);
    const int region = stream.currentRegion();
    EXPECT_GE(filler_offset, stream.regionOffset(region)) << "round " << round;
    EXPECT_LE(offset + kBlock, stream.regionOffset(region) + stream.regionBytes());
    stream.bindRange(GL_UNIFORM_BUFFER, 0, offset, kBlock);
    glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 1, out.id(), GLintptr(std::size_t(round) * kBlock),
                      GLsizeiptr(kBlock));
    copy.use();
    glDispatchCompute(1, 1, 1);
  }
  EXPECT_GT(stream.regionBytes(), first_region_bytes);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const std::vector<glm::uvec4> copied = readBuffer<glm::uvec4>(out, kRounds * 16);
  for (int round = 0; round < kRounds; ++round) {
    const std::vector<glm::uvec4> expected = roundValues(round, 16);
    for (std::size_t i = 0; i < 16; ++i)
      ASSERT_EQ(copied[std::size_t(round) * 16 + i], expected[i]) << "round " << round;
  }
}

// Draws queued behind one another, each reading its round's data when it is rasterised (a
// storage buffer, which a driver reads in place; llvmpipe rasterises at its next flush): 48
// rounds of 64 KiB, three times around the first ring's 768 KiB, each round's draw writing its
// own pixel. Every pixel holds its own round's values, so no region was written again while a
// queued draw still had to read it. (Without the ring's fences, which also flush llvmpipe's
// queue, the early rounds' pixels show later rounds' data: checked.)
TEST_F(StreamBufferTest, NoRoundIsOverwrittenBeforeItsDrawsReadIt) {
  constexpr int kRounds = 48, kSide = 8;
  constexpr std::size_t kRoundBytes = 64u << 10;
  Framebuffer framebuffer;
  const Texture target = Texture::make2D(GL_RGBA32F, kSide, kSide);
  framebuffer.attachColor(0, target);
  framebuffer.setDrawBuffers(1);
  framebuffer.bind();
  const Program draw = buildProgram(
      {{GL_VERTEX_SHADER, "v.glsl"}, {GL_FRAGMENT_SHADER, "f.glsl"}}, "",
      test::glslSources({{"v.glsl",
                          "void main() { vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
                          "  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0); }\n"},
                         {"f.glsl",
                          "layout(std430, binding = 0) readonly buffer Round { uvec4 values[]; };\n"
                          "layout(location = 0) out vec4 color;\n"
                          "void main() { color = vec4(values[0].xz, values[4095].xz); }\n"}}));
  draw.use();
  const VertexArray vertices;
  vertices.bind();
  StreamBuffer stream;
  const PipelineScope whole_target({.viewport = PixelRect{0, 0, kSide, kSide}});
  for (int round = 0; round < kRounds; ++round) {
    stream.beginRound({kRoundBytes});
    const std::vector<glm::uvec4> values = roundValues(round, kRoundBytes / sizeof(glm::uvec4));
    stream.bindRange(GL_SHADER_STORAGE_BUFFER, 0, stream.push(values), kRoundBytes);
    const PipelineScope own_pixel({.scissor = PixelRect{round % kSide, round / kSide, 1, 1}});
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glFinish();
  EXPECT_LE(std::size_t(stream.regions()) * stream.regionBytes(), StreamBuffer::kMaxRingBytes);
  const image::Image image = readTexture(target, 4);
  for (int round = 0; round < kRounds; ++round) {
    const float* pixel = image.pixel(round % kSide, kSide - 1 - round / kSide);
    EXPECT_EQ(pixel[0], float(round)) << "round " << round;
    EXPECT_EQ(pixel[1], float(round * 1000)) << "round " << round;
    EXPECT_EQ(pixel[2], float(round)) << "round " << round;
    EXPECT_EQ(pixel[3], float(round * 1000 + 4095)) << "round " << round;
  }
}

TEST_F(StreamBufferTest, APushBeyondItsRoundIsRefused) {
  StreamBuffer stream;
  EXPECT_THROW(stream.push(nullptr, 0), std::logic_error);  // no round begun yet
  stream.beginRound({64});
  // More than the round began with; a reserve counts as taken (a block bound at its declared
  // size must lie inside the round).
  const std::vector<char> too_much(stream.alignment() + 64, 'x');
  EXPECT_THROW(stream.push(too_much.data(), too_much.size()), std::logic_error);
  EXPECT_THROW(stream.push(nullptr, 0, too_much.size()), std::logic_error);
  EXPECT_NO_THROW(stream.push(too_much.data(), 64));
  EXPECT_THROW(stream.push(too_much.data(), 1), std::logic_error);  // the round is used up
}

}  // namespace
}  // namespace gib::rt::gl
