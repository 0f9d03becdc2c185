#include "realtime/gl/pass_profiler.h"

#include "metrics/pass_timing_summary.h"

#include "realtime/gl/gl.h"
#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/objects.h"
#include "realtime/gl/shader_library.h"
#include "support/gl_test_context.h"
#include "support/glsl_sources.h"

#include <gtest/gtest.h>

#include <chrono>
#include <optional>
#include <thread>

namespace gib::rt::gl {
namespace {

using test::GlTest;

// A fullscreen triangle whose fragments do some arithmetic: enough work per draw that a pass of
// a few dozen draws takes measurable time on llvmpipe.
const GlslLookup kSources =
    test::glslSources({{"test/fullscreen.vert.glsl",
                        "void main() {\n"
                        "  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
                        "  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n"
                        "}\n"},
                       {"test/busy.frag.glsl",
                        "layout(location = 0) out vec4 color;\n"
                        "void main() {\n"
                        "  float v = 0.0;\n"
                        "  for (int i = 0; i < 64; ++i) v += sin(gl_FragCoord.x * 0.01 * float(i) "
                        "+ gl_FragCoord.y);\n"
                        "  color = vec4(v, 0.0, 0.0, 1.0);\n"
                        "}\n"}});

// A float target and a program that draws into it.
class Canvas {
 public:
  static constexpr int kSize = 256;

  Canvas()
      : target_(Texture::make2D(GL_RGBA32F, kSize, kSize)),
        program_(buildProgram({{GL_VERTEX_SHADER, "test/fullscreen.vert.glsl"},
                               {GL_FRAGMENT_SHADER, "test/busy.frag.glsl"}},
                              "", kSources)) {
    framebuffer_.attachColor(0, target_);
    framebuffer_.setDrawBuffers(1);
    framebuffer_.checkComplete();
  }

  void clear() const {
    const float color[4] = {0.5f, 0.5f, 0.5f, 1};
    glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, color);
  }

  void draw(int count) const {
    framebuffer_.bind();
    glViewport(0, 0, kSize, kSize);
    program_.use();
    vertex_array_.bind();
    for (int i = 0; i < count; ++i) drawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

 private:
  Texture target_;
  Framebuffer framebuffer_;
  VertexArray vertex_array_;
  Program program_;
};

class PassProfilerTest : public GlTest {
 protected:
  // GL objects are made here, not in the constructor: the context is current only after
  // GlTest::SetUp.
  void SetUp() override {
    GlTest::SetUp();
    canvas_.emplace();
  }
  void TearDown() override {
    canvas_.reset();
    GlTest::TearDown();
  }

  void clear() { canvas_->clear(); }
  void draw(int count) { canvas_->draw(count); }

  // Runs `frames` frames of a pass "work" holding one clear.
  void clearFrames(PassProfiler& profiler, int frames, bool measured = true) {
    for (int f = 0; f < frames; ++f) {
      profiler.beginFrame(measured);
      {
        auto scope = profiler.pass("work");
        clear();
      }
      profiler.endFrame();
    }
  }

  static const PassRecord& find(const ProfileRecord& record, std::string_view path) {
    for (const PassRecord& pass : record.passes)
      if (pass.path == path) return pass;
    ADD_FAILURE() << "no pass " << path;
    return record.passes.front();
  }

 private:
  std::optional<Canvas> canvas_;
};

TEST_F(PassProfilerTest, NestedPassesGetPathsAndDepths) {
  PassProfiler profiler;
  profiler.beginFrame();
  {
    auto a = profiler.pass("a");
    clear();
    {
      auto b = profiler.pass("b");
      clear();
    }
  }
  profiler.endFrame();
  const ProfileRecord record = profiler.finish();
  ASSERT_EQ(record.passes.size(), 3u);
  EXPECT_EQ(record.passes[0].path, "frame");
  EXPECT_EQ(record.passes[1].path, "frame/a");
  EXPECT_EQ(record.passes[2].path, "frame/a/b");
  EXPECT_EQ(record.passes[2].name, "b");
  EXPECT_EQ(record.passes[0].depth, 0);
  EXPECT_EQ(record.passes[2].depth, 2);
  EXPECT_EQ(record.measured_frames, 1);
  // Nested GPU intervals: the frame holds "a", which holds "b".
  EXPECT_GE(record.passes[0].gpu_ms[0], record.passes[1].gpu_ms[0]);
  EXPECT_GE(record.passes[1].gpu_ms[0], record.passes[2].gpu_ms[0]);
}

TEST_F(PassProfilerTest, RepeatedEntriesOfAPassInAFrameAreSummed) {
  PassProfiler profiler(/*precise=*/true);
  constexpr auto kNap = std::chrono::milliseconds(2);
  for (int frame = 0; frame < 2; ++frame) {
    profiler.beginFrame();
    // Our own timestamps inside each entry: the pass's GPU time must cover all three.
    double inner_gpu_ms = 0;
    for (int entry = 0; entry < 3; ++entry) {
      auto scope = profiler.pass("light");
      Query begin(GL_TIMESTAMP), end(GL_TIMESTAMP);
      glQueryCounter(begin.id(), GL_TIMESTAMP);
      draw(2);
      glQueryCounter(end.id(), GL_TIMESTAMP);
      std::this_thread::sleep_for(kNap);
      inner_gpu_ms += double(end.result() - begin.result()) * 1e-6;
    }
    profiler.endFrame();
    const ProfileRecord record = profiler.finish();
    const PassRecord& light = find(record, "frame/light");
    ASSERT_EQ(light.calls.size(), std::size_t(frame + 1));
    EXPECT_EQ(light.calls[frame], 3);
    EXPECT_GE(light.gpu_ms[frame] + 1e-9, inner_gpu_ms);
    EXPECT_GE(light.cpu_ms[frame], 3 * 2.0);  // each entry slept 2 ms
    EXPECT_EQ(find(record, "frame").calls[frame], 1);
  }
}

TEST_F(PassProfilerTest, GpuCommandsAreCountedPerPassWithTheirInnerPasses) {
  PassProfiler profiler;
  profiler.beginFrame(/*measured=*/false);
  draw(5);  // a warm-up frame's draws are not recorded
  profiler.endFrame();
  for (int frame = 0; frame < 3; ++frame) {
    profiler.beginFrame();
    draw(1);  // in the frame, outside every pass
    {
      auto outer = profiler.pass("outer");
      draw(2);
      for (int entry = 1; entry <= 2; ++entry) {
        auto inner = profiler.pass("inner");
        draw(entry + frame);
      }
    }
    profiler.endFrame();
  }
  const ProfileRecord record = profiler.finish();
  // Inner: (1 + f) + (2 + f) in frame f; outer adds its own 2; the frame its 1.
  EXPECT_EQ(find(record, "frame/outer/inner").gpu_commands, (std::vector<int>{3, 5, 7}));
  EXPECT_EQ(find(record, "frame/outer").gpu_commands, (std::vector<int>{5, 7, 9}));
  EXPECT_EQ(find(record, "frame").gpu_commands, (std::vector<int>{6, 8, 10}));
  const std::vector<metrics::PassTiming> rows = metrics::summarizeProfile(record).passes;
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].gpu_commands_per_frame, 8.0);
  EXPECT_EQ(rows[2].gpu_commands_per_frame, 5.0);
}

TEST_F(PassProfilerTest, WarmUpFramesAreCountedButNotMeasured) {
  PassProfiler profiler;
  profiler.beginFrame(/*measured=*/false);
  { auto setup = profiler.pass("one-off set-up"); }
  profiler.endFrame();
  clearFrames(profiler, 2, /*measured=*/false);
  clearFrames(profiler, 5);
  const ProfileRecord record = profiler.finish();
  EXPECT_EQ(record.warmup_frames, 3);
  EXPECT_EQ(record.measured_frames, 5);
  ASSERT_EQ(record.passes.size(), 2u);  // the set-up pass ran in warm-up frames only
  for (const PassRecord& pass : record.passes) {
    EXPECT_EQ(pass.gpu_ms.size(), 5u) << pass.path;
    EXPECT_EQ(pass.calls, std::vector<int>(5, 1)) << pass.path;
  }
}

TEST_F(PassProfilerTest, APassFirstSeenInALaterFrameIsZeroBefore) {
  PassProfiler profiler(/*precise=*/true);
  for (int frame = 0; frame < 4; ++frame) {
    profiler.beginFrame();
    if (frame == 2) {
      auto late = profiler.pass("late");
      clear();
    }
    profiler.endFrame();
  }
  const ProfileRecord record = profiler.finish();
  const PassRecord& late = find(record, "frame/late");
  EXPECT_EQ(late.calls, (std::vector<int>{0, 0, 1, 0}));
  ASSERT_EQ(late.cpu_ms.size(), 4u);
  ASSERT_EQ(late.gpu_ms.size(), 4u);
  EXPECT_EQ(late.cpu_ms[0], 0.0);
  EXPECT_GT(late.cpu_ms[2], 0.0);
  EXPECT_EQ(late.gpu_ms[3], 0.0);
}

TEST_F(PassProfilerTest, PreciseModeRecordsTheCpuClockAndReportsIt) {
  PassProfiler profiler(/*precise=*/true);
  clearFrames(profiler, 3);
  const ProfileRecord record = profiler.finish();
  EXPECT_TRUE(record.precise);
  EXPECT_EQ(record.reported_clock, "cpu");
  for (const PassRecord& pass : record.passes) {
    ASSERT_EQ(pass.cpu_ms.size(), 3u) << pass.path;
    EXPECT_EQ(pass.gpu_ms.size(), 3u) << pass.path;
    EXPECT_GT(pass.cpu_ms[0], 0.0) << pass.path;
    EXPECT_EQ(&record.reported(pass), &pass.cpu_ms);
  }
}

TEST_F(PassProfilerTest, WithoutPreciseModeThereIsNoCpuClock) {
  PassProfiler profiler;
  clearFrames(profiler, 3);
  const ProfileRecord record = profiler.finish();
  EXPECT_FALSE(record.precise);
  EXPECT_EQ(record.reported_clock, "gpu");
  for (const PassRecord& pass : record.passes) {
    EXPECT_TRUE(pass.cpu_ms.empty()) << pass.path;
    EXPECT_EQ(pass.gpu_ms.size(), 3u) << pass.path;
  }
}

TEST_F(PassProfilerTest, PassesEndedOutOfOrderAreALogicErrorAndTheFrameIsDropped) {
  PassProfiler profiler;
  profiler.beginFrame();
  {
    std::optional<PassProfiler::Scope> outer(profiler.pass("outer"));
    std::optional<PassProfiler::Scope> inner(profiler.pass("inner"));
    outer.reset();  // ends before the pass opened inside it
  }
  EXPECT_THROW(profiler.endFrame(), std::logic_error);
  clearFrames(profiler, 2);  // the profiler goes on
  const ProfileRecord record = profiler.finish();
  EXPECT_EQ(record.measured_frames, 2);
  EXPECT_EQ(find(record, "frame/work").gpu_ms.size(), 2u);
}

TEST_F(PassProfilerTest, EndingAFrameWithAPassOpenIsALogicErrorAndKeepsTheFrame) {
  PassProfiler profiler;
  profiler.beginFrame();
  {
    auto open = profiler.pass("open");
    EXPECT_THROW(profiler.endFrame(), std::logic_error);
  }
  profiler.endFrame();
  EXPECT_EQ(profiler.finish().measured_frames, 1);
}

TEST_F(PassProfilerTest, APassOutsideAFrameIsANoOp) {
  PassProfiler profiler;
  {
    auto scope = profiler.pass("nowhere");
    clear();
  }
  const ProfileRecord record = profiler.finish();
  EXPECT_EQ(record.measured_frames, 0);
  ASSERT_EQ(record.passes.size(), 1u);
  EXPECT_EQ(record.passes[0].path, "frame");
}

TEST_F(PassProfilerTest, MisuseIsRefused) {
  EXPECT_THROW(PassProfiler(false, -1), std::invalid_argument);
  PassProfiler profiler;
  EXPECT_THROW(profiler.endFrame(), std::logic_error);
  profiler.beginFrame();
  EXPECT_THROW((void)profiler.pass("a/b"), std::invalid_argument);  // '/' separates path names
  EXPECT_THROW(profiler.beginFrame(), std::logic_error);
  EXPECT_THROW(profiler.finish(), std::logic_error);
  profiler.endFrame();
}

TEST_F(PassProfilerTest, FinishCollectsEveryFrameStillInFlight) {
  // Latency 2 with 12 frames: beginFrame collects what has landed and waits for the rest only
  // beyond two frames in flight; finish drains whatever is left.
  PassProfiler profiler(false, 2);
  clearFrames(profiler, 12);
  const ProfileRecord record = profiler.finish();
  EXPECT_EQ(record.measured_frames, 12);
  EXPECT_EQ(find(record, "frame/work").gpu_ms.size(), 12u);
  EXPECT_EQ(find(record, "frame/work").calls, std::vector<int>(12, 1));
  // Profiling goes on after finish, with the queries recycled.
  clearFrames(profiler, 3);
  EXPECT_EQ(profiler.finish().measured_frames, 15);
}

TEST_F(PassProfilerTest, TimestampsOfAHeavyPassAreAboveZero) {
  // llvmpipe's timestamp queries return real times for rasterisation work.
  PassProfiler profiler;
  for (int frame = 0; frame < 3; ++frame) {
    profiler.beginFrame();
    {
      auto heavy = profiler.pass("heavy");
      draw(40);
    }
    profiler.endFrame();
  }
  const ProfileRecord record = profiler.finish();
  for (double ms : find(record, "frame/heavy").gpu_ms) EXPECT_GT(ms, 0.0);
}

TEST_F(PassProfilerTest, ARealProfileSummarisesIntoATable) {
  PassProfiler profiler(/*precise=*/true);
  for (int frame = 0; frame < 6; ++frame) {
    profiler.beginFrame(/*measured=*/frame >= 2);
    {
      auto lighting = profiler.pass("lighting");
      for (int light = 0; light < 2; ++light) {
        auto shadow = profiler.pass("shadow map");
        draw(4);
      }
    }
    {
      auto final_pass = profiler.pass("final");
      draw(1);
    }
    profiler.endFrame();
  }
  const ProfileRecord record = profiler.finish();
  const metrics::PassTimings timings = metrics::summarizeProfile(record);
  const std::vector<metrics::PassTiming>& rows = timings.passes;
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[2].path, "frame/lighting/shadow map");
  EXPECT_EQ(rows[2].calls_per_frame, 2.0);
  EXPECT_GT(rows[1].share, 0.0);
  EXPECT_LE(rows[1].share + rows[3].share, 1.0);
  const std::string table = metrics::formatPassTable(timings);
  EXPECT_NE(table.find("    shadow map"), std::string::npos) << table;
  EXPECT_NE(table.find("2 warm-up and 4 measured frames"), std::string::npos) << table;
}

}  // namespace
}  // namespace gib::rt::gl
