// The G-buffer's contents are checked pixel by pixel against Embree in pixel_agreement_test.cpp;
// this file covers the rest of its contract.
#include "realtime/gbuffer/gbuffer.h"

#include "realtime/cube_faces.h"
#include "realtime/gbuffer/gbuffer_views_shared.h"
#include "realtime/gl/pass_profiler.h"
#include "scene/builtin_scenes.h"
#include "support/gl_test_context.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

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
  // The back wall's triangle, seen from its front: +(t + 1), t an index into the scene's list.
  const float code = albedo.pixel(32, 8)[3];
  EXPECT_GE(code, 1.0f);
  EXPECT_LE(code, float(cornell.triangleCount()));
  EXPECT_EQ(code, std::floor(code));
}

TEST_F(GlTest, GBufferOfAnotherShapeThanTheCameraIsRefused) {
  const scene::Scene cornell = scene::loadScene("cornell");
  const GpuScene gpu(cornell, 64, 64);
  GBuffer gbuffer(64, 32);
  EXPECT_THROW(gbuffer.render(gpu), std::logic_error);
}

// renderViews draws many views per instanced draw, each into its own viewport: the buffer holds in
// each rectangle exactly what that view drawn alone gives, bit for bit, and nothing outside the
// rectangles; choosing the viewport in the geometry shader gives the same buffer. 240 cube faces
// of 8² texels: 15 draws of gpu::kMaxGBufferViewsPerDraw views.
TEST_F(GlTest, ViewsDrawnTogetherAreEachViewDrawnAlone) {
  const scene::Scene cornell = scene::loadScene("cornell");
  const GpuScene gpu(cornell, 64, 64);
  constexpr int kTile = 8, kColumns = 20, kRows = 12, kWidth = kColumns * kTile + 3;
  std::vector<GBufferView> views;
  for (int i = 0; i < kColumns * kRows; ++i) {
    const glm::vec3 eye(40.0f + 11.0f * float(i % 43), 30.0f + 13.0f * float(i % 37),
                        20.0f + 2.1f * float(i));
    const int face = i % 6;
    views.push_back({cubeFaceViewProjection(eye, face, 0.1f, 1e4f), eye, (i % kColumns) * kTile,
                     (i / kColumns) * kTile, kTile, kTile});
  }
  ASSERT_GT(int(views.size()), gpu::kMaxGBufferViewsPerDraw);
  GBuffer together(kWidth, kRows * kTile), alone(kWidth, kRows * kTile),
      geometry(kWidth, kRows * kTile);
  together.renderViews(gpu, views);
  const image::Image all = gl::readTexture(together.position(), 4);
  geometry.selectViewportsInGeometryShader();
  geometry.renderViews(gpu, views);
  const image::Image all_geometry = gl::readTexture(geometry.position(), 4);
  ASSERT_TRUE(std::equal(all.data().begin(), all.data().end(), all_geometry.data().begin()))
      << "the geometry shader's viewports";
  std::vector<bool> inside(std::size_t(all.width()) * std::size_t(all.height()), false);
  for (std::size_t v = 0; v < views.size(); ++v) {
    const GBufferView& view = views[v];
    for (int y = view.y; y < view.y + view.height; ++y)
      for (int x = view.x; x < view.x + view.width; ++x)
        inside[std::size_t((all.height() - 1 - y) * all.width() + x)] = true;
    if (v % 7 != 0) continue;  // each view alone: a sample of them
    alone.renderViews(gpu, {view});
    const image::Image one = gl::readTexture(alone.position(), 4);
    for (int y = 0; y < one.height(); ++y)
      for (int x = 0; x < one.width(); ++x) {
        const int gl_y = one.height() - 1 - y;  // image rows run top down, GL's bottom up
        const bool mine =
            x >= view.x && x < view.x + view.width && gl_y >= view.y && gl_y < view.y + view.height;
        for (int c = 0; c < 4; ++c) {
          if (mine) {
            ASSERT_EQ(one.pixel(x, y)[c], all.pixel(x, y)[c])
                << "view " << v << " at " << x << "," << gl_y;
          } else {
            ASSERT_EQ(one.pixel(x, y)[3], -1.0f) << "view " << v << " drew outside its rectangle";
          }
        }
      }
  }
  int covered = 0;
  for (int y = 0; y < all.height(); ++y)
    for (int x = 0; x < all.width(); ++x) {
      const bool in = inside[std::size_t(y * all.width() + x)];
      if (!in) {
        EXPECT_EQ(all.pixel(x, y)[3], -1.0f) << x << "," << y;
      }
      if (in && all.pixel(x, y)[3] >= 0.0f) ++covered;
    }
  EXPECT_GT(covered, kColumns * kRows * kTile * kTile / 2);  // views from inside the box see walls
}

// Each view draws only the triangle chunks its frustum may touch (view_culling.h): the buffer is
// bit for bit the one every view drawing every triangle gives, on the chamber (3 384 triangles),
// seen from the six faces of 64 eyes through the hall (the irradiance volume's views), while the
// views draw well under half of the triangles.
TEST_F(GlTest, CulledViewsDrawWhatEveryTriangleDraws) {
  const scene::Scene chamber = scene::loadScene("chamber");
  const GpuScene gpu(chamber, 64, 64);
  constexpr int kTile = 16, kEyes = 64, kColumns = 24;
  std::vector<GBufferView> views;
  std::size_t vertices_drawn = 0;
  for (int i = 0; i < 6 * kEyes; ++i) {
    const int e = i / 6;
    const glm::vec3 eye(-3.5f + 7.0f * float(e % 4) / 3.0f, 0.5f + 6.0f * float((e / 4) % 4) / 3.0f,
                        0.5f + 11.0f * float(e / 16) / 3.0f);
    const glm::mat4 view_projection = cubeFaceViewProjection(eye, i % 6, 0.01f, 40.0f);
    views.push_back(
        {view_projection, eye, (i % kColumns) * kTile, (i / kColumns) * kTile, kTile, kTile});
    std::vector<DrawArraysIndirectCommand> records;
    appendVisibleRuns(gpu.chunks(), view_projection, 0, records);
    for (const DrawArraysIndirectCommand& r : records) vertices_drawn += r.count;
  }
  const int rows = (int(views.size()) + kColumns - 1) / kColumns;
  GBuffer culled(kColumns * kTile, rows * kTile), everything(kColumns * kTile, rows * kTile);
  culled.renderViews(gpu, views);
  everything.drawViewsWithoutCulling();
  everything.renderViews(gpu, views);
  for (const auto& texture : {&GBuffer::position, &GBuffer::normal, &GBuffer::albedo}) {
    const image::Image a = gl::readTexture((culled.*texture)(), 4);
    const image::Image b = gl::readTexture((everything.*texture)(), 4);
    ASSERT_TRUE(std::equal(a.data().begin(), a.data().end(), b.data().begin()));
  }
  const image::Image position = gl::readTexture(culled.position(), 4);
  int covered = 0;
  for (int y = 0; y < position.height(); ++y)
    for (int x = 0; x < position.width(); ++x) covered += position.pixel(x, y)[3] >= 0.0f;
  EXPECT_GT(covered, 6 * kEyes * kTile * kTile / 2);  // the views see the hall
  EXPECT_LT(double(vertices_drawn), 0.5 * double(views.size() * gpu.vertexCount()));
}

}  // namespace
}  // namespace gib::rt
