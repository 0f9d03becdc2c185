#include "realtime/gl/context.h"
#include "realtime/gl/gl.h"
#include "realtime/gl/objects.h"
#include "support/gl_test_context.h"

#include "common/input_error.h"

#include <gtest/gtest.h>

namespace gib::rt::gl {
namespace {

using test::GlTest;
using test::glTestContext;

TEST_F(GlTest, ContextIsOpenGl45CoreAndSaysWhatItRunsOn) {
  const GlIdentity& id = glTestContext().identity();
  EXPECT_FALSE(id.renderer.empty());
  EXPECT_FALSE(id.vendor.empty());
  EXPECT_FALSE(id.device.empty());
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_GE(major * 10 + minor, 45);
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
}

TEST_F(GlTest, DebugOutputReportsAGlError) {
  // The fixture's promise (any GL error fails a test) rests on this.
  glBindTexture(GL_TEXTURE_2D, 0xdeadbeef);  // not a texture name: GL_INVALID_OPERATION
  std::vector<std::string> errors = glTestContext().takeDebugErrors();
  EXPECT_FALSE(errors.empty());
}

TEST(GlContext, UnknownDeviceIsAnInputErrorNamingTheChoices) {
  ContextOptions options;
  options.device = "gpu7";
  try {
    Context::create(options);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("surfaceless"), std::string::npos) << e.what();
  }
  glTestContext().makeCurrent();
}

TEST(GlContext, DeviceIndexOutOfRangeIsAnInputError) {
  ContextOptions options;
  options.device = "999";
  EXPECT_THROW(Context::create(options), InputError);
  glTestContext().makeCurrent();
}

TEST_F(GlTest, FloatTargetsHoldValuesAboveOneAndBelowZero) {
  Texture texture = Texture::make2D(GL_RGBA32F, 4, 3);
  Framebuffer framebuffer;
  framebuffer.attachColor(0, texture);
  framebuffer.setDrawBuffers(1);
  framebuffer.checkComplete();
  const float value[4] = {-3.5f, 1.0e4f, 0.25f, 1.0f};
  glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, value);
  image::Image image = readPixels(framebuffer, 0, 4, 3, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) {
      EXPECT_EQ(image.pixel(x, y)[0], -3.5f);
      EXPECT_EQ(image.pixel(x, y)[1], 1.0e4f);
      EXPECT_EQ(image.pixel(x, y)[2], 0.25f);
    }
}

TEST_F(GlTest, ReadPixelsPutsGlsBottomRowAtTheBottomOfTheImage) {
  Texture texture = Texture::make2D(GL_R32F, 2, 2);
  const float values[4] = {1, 2, 3, 4};  // GL rows: (1,2) at the bottom, (3,4) on top
  texture.upload(values, GL_RED);
  image::Image image = readTexture(texture, 1);
  EXPECT_EQ(image.pixel(0, 0)[0], 3.0f);
  EXPECT_EQ(image.pixel(1, 0)[0], 4.0f);
  EXPECT_EQ(image.pixel(0, 1)[0], 1.0f);
}

TEST_F(GlTest, TimestampQueriesReturn) {
  Query begin(GL_TIMESTAMP), end(GL_TIMESTAMP);
  glQueryCounter(begin.id(), GL_TIMESTAMP);
  Texture texture = Texture::make2D(GL_RGBA32F, 256, 256);
  Framebuffer framebuffer;
  framebuffer.attachColor(0, texture);
  const float value[4] = {1, 2, 3, 4};
  glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, value);
  glQueryCounter(end.id(), GL_TIMESTAMP);
  const std::uint64_t t0 = begin.result(), t1 = end.result();
  EXPECT_GT(t0, 0u);
  EXPECT_GE(t1, t0);
  EXPECT_TRUE(end.available());
}

}  // namespace
}  // namespace gib::rt::gl
