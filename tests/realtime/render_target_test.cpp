#include "realtime/render_target.h"

#include "support/gl_test_context.h"

#include <gtest/gtest.h>

#include <vector>

namespace gib::rt {
namespace {

using test::GlTest;

TEST_F(GlTest, RenderTargetClearsToAColourAndReadsItBackAsRgb) {
  RenderTarget target(5, 3);
  EXPECT_EQ(target.color().format(), GLenum(GL_RGBA32F));
  EXPECT_EQ(target.depth().format(), GLenum(GL_DEPTH_COMPONENT32F));
  target.bind();
  GLint viewport[4] = {};
  glGetIntegerv(GL_VIEWPORT, viewport);
  EXPECT_EQ(viewport[2], 5);
  EXPECT_EQ(viewport[3], 3);

  glDepthMask(GL_FALSE);  // left off by an earlier pass: the clear still clears
  target.clear(0.25f, -2.0f, 1.0e3f);
  const image::Image image = target.read();
  ASSERT_EQ(image.width(), 5);
  ASSERT_EQ(image.height(), 3);
  ASSERT_EQ(image.channels(), 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) {
      EXPECT_EQ(image.pixel(x, y)[0], 0.25f);
      EXPECT_EQ(image.pixel(x, y)[1], -2.0f);
      EXPECT_EQ(image.pixel(x, y)[2], 1.0e3f);
    }
  std::vector<float> depth(5 * 3, 0.0f);
  glGetTextureImage(target.depth().id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                    GLsizei(depth.size() * sizeof(float)), depth.data());
  for (float d : depth) EXPECT_EQ(d, 1.0f);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace
}  // namespace gib::rt
