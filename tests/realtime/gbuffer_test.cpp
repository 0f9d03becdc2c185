// The G-buffer's contents are checked pixel by pixel against Embree in pixel_agreement_test.cpp;
// this file covers the rest of its contract.
#include "realtime/gbuffer/gbuffer.h"

#include "realtime/gl/pass_profiler.h"
#include "scene/builtin_scenes.h"
#include "support/gl_test_context.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

namespace gib::rt {
namespace {

using test::GlTest;

TEST_F(GlTest, GBufferRecordsItsPassWithTheProfiler) {
  const scene::Scene cornell = scene::loadScene("cornell");
  const GpuScene gpu(cornell, 32, 32);
  GBuffer gbuffer(32, 32);
  gl::PassProfiler profiler(/*precise=*/true);
  profiler.beginFrame();
  gbuffer.render(gpu, &profiler);
  profiler.endFrame();
  const ProfileRecord record = profiler.finish();
  EXPECT_TRUE(std::any_of(record.passes.begin(), record.passes.end(),
                          [](const PassRecord& pass) { return pass.name == "g-buffer"; }));
}

TEST_F(GlTest, GBufferMarksBackgroundPixels) {
  // The Cornell box seen through a wide image: its left and right edges look past the box.
  const scene::Scene cornell = scene::loadScene("cornell");
  const GpuScene gpu(cornell, 64, 16);
  GBuffer gbuffer(64, 16);
  gbuffer.render(gpu);
  const image::Image position = gl::readTexture(gbuffer.position(), 4);
  const image::Image normal = gl::readTexture(gbuffer.normal(), 4);
  const image::Image albedo = gl::readTexture(gbuffer.albedo(), 4);
  EXPECT_EQ(position.pixel(0, 8)[3], -1.0f);
  EXPECT_EQ(normal.pixel(0, 8)[3], -1.0f);
  EXPECT_EQ(albedo.pixel(0, 8)[3], 0.0f);
  EXPECT_GT(position.pixel(32, 8)[3], 800.0f);  // the back of the box, past its open front
  EXPECT_GE(normal.pixel(32, 8)[3], 0.0f);
  EXPECT_EQ(albedo.pixel(32, 8)[3], 1.0f);
}

TEST_F(GlTest, GBufferOfAnotherShapeThanTheCameraIsRefused) {
  const scene::Scene cornell = scene::loadScene("cornell");
  const GpuScene gpu(cornell, 64, 64);
  GBuffer gbuffer(64, 32);
  EXPECT_THROW(gbuffer.render(gpu), std::logic_error);
}

}  // namespace
}  // namespace gib::rt
