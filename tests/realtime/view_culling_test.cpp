// Per-view culling (realtime/gpu_scene/view_culling.h) may only leave out triangles a view cannot
// rasterise: checked here on its own terms (boxes against frusta, chunks, runs), and in
// gbuffer_test.cpp on pixels.
#include "realtime/gpu_scene/view_culling.h"

#include "realtime/cube_faces.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

namespace gib::rt {
namespace {

const glm::mat4 kFrontFace = cubeFaceViewProjection(glm::vec3(0.0f), 4, 0.1f, 100.0f);  // +z

TEST(ViewCulling, BoxesAreCulledOnlyWhenWhollyOutsideOnePlane) {
  const glm::vec3 axis = kCubeFaceAxis[4];
  ASSERT_EQ(axis, glm::vec3(0, 0, 1));
  // Inside, straddling a side plane, straddling the near plane: kept.
  EXPECT_FALSE(boxOutsideFrustum(kFrontFace, glm::vec3(-1, -1, 5), glm::vec3(1, 1, 6)));
  EXPECT_FALSE(boxOutsideFrustum(kFrontFace, glm::vec3(4, -1, 5), glm::vec3(6, 1, 6)));
  EXPECT_FALSE(boxOutsideFrustum(kFrontFace, glm::vec3(-1, -1, -1), glm::vec3(1, 1, 1)));
  // Behind the eye, beside the 90° cone, past the far plane: culled.
  EXPECT_TRUE(boxOutsideFrustum(kFrontFace, glm::vec3(-1, -1, -6), glm::vec3(1, 1, -5)));
  EXPECT_TRUE(boxOutsideFrustum(kFrontFace, glm::vec3(6, -1, 5), glm::vec3(7, 1, 5.9f)));
  EXPECT_TRUE(boxOutsideFrustum(kFrontFace, glm::vec3(-1, -1, 101), glm::vec3(1, 1, 102)));
  // A box around the corner of the cone, outside two planes but none wholly: kept (conservative).
  EXPECT_FALSE(boxOutsideFrustum(kFrontFace, glm::vec3(4.5f, 4.5f, 4), glm::vec3(6, 6, 5)));
}

// The property rasterisation needs: a triangle with a point in the clip volume is never culled.
// 20 000 random small triangles against the six faces of a cube around a random eye; a triangle
// counts as seen when any point of a 6×6 barycentric grid on it is strictly inside.
TEST(ViewCulling, NoChunkWithAPointInAViewIsCulled) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> coordinate(-10.0f, 10.0f), offset(-1.5f, 1.5f);
  int seen = 0, culled = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const glm::vec3 eye(coordinate(random), coordinate(random), coordinate(random));
    const glm::vec3 a(coordinate(random), coordinate(random), coordinate(random));
    const glm::vec3 triangle[3] = {a, a + glm::vec3(offset(random), offset(random), offset(random)),
                                   a + glm::vec3(offset(random), offset(random), offset(random))};
    const std::vector<TriangleChunk> chunks = triangleChunks(triangle, 1);
    ASSERT_EQ(chunks.size(), 1u);
    const glm::mat4 view = cubeFaceViewProjection(eye, trial % 6, 0.05f, 40.0f);
    bool inside = false;
    for (int i = 0; i <= 5 && !inside; ++i)
      for (int j = 0; i + j <= 5 && !inside; ++j) {
        const float u = float(i) / 5.0f, v = float(j) / 5.0f;
        const glm::vec3 p =
            triangle[0] + u * (triangle[1] - triangle[0]) + v * (triangle[2] - triangle[0]);
        const glm::vec4 clip = view * glm::vec4(p, 1.0f);
        inside = clip.w > 0.0f && glm::abs(clip.x) < clip.w && glm::abs(clip.y) < clip.w &&
                 glm::abs(clip.z) < clip.w;
      }
    const bool out = boxOutsideFrustum(view, chunks[0].lo, chunks[0].hi);
    if (inside) {
      ++seen;
      ASSERT_FALSE(out) << "trial " << trial << ": a triangle inside the view was culled";
    }
    if (out) ++culled;
  }
  // The test means something only if both cases occur often.
  EXPECT_GT(seen, 2000);
  EXPECT_GT(culled, 8000);
}

TEST(ViewCulling, ChunksCoverTheListInOrderWithTheirBounds) {
  std::vector<glm::vec3> positions;
  for (int t = 0; t < 10; ++t)
    for (int k = 0; k < 3; ++k) positions.push_back(glm::vec3(float(t), float(k), -float(t * k)));
  const std::vector<TriangleChunk> chunks = triangleChunks(positions, 4);
  ASSERT_EQ(chunks.size(), 3u);  // 4 + 4 + 2 triangles
  GLint next = 0;
  for (const TriangleChunk& chunk : chunks) {
    EXPECT_EQ(chunk.first_vertex, next);
    next += chunk.vertex_count;
    for (GLint i = chunk.first_vertex; i < chunk.first_vertex + chunk.vertex_count; ++i) {
      EXPECT_TRUE(glm::all(glm::greaterThanEqual(positions[std::size_t(i)], chunk.lo)));
      EXPECT_TRUE(glm::all(glm::lessThanEqual(positions[std::size_t(i)], chunk.hi)));
    }
  }
  EXPECT_EQ(next, GLint(positions.size()));
  EXPECT_EQ(chunks[1].lo, glm::vec3(4, 0, -14));
  EXPECT_EQ(chunks[1].hi, glm::vec3(7, 2, 0));
  EXPECT_THROW(triangleChunks(positions, 0), std::invalid_argument);
}

TEST(ViewCulling, VisibleChunksInARowMakeOneRecord) {
  // Five one-triangle chunks along +z at z = 5, −5, 6, 7, −6: seen from the origin along +z,
  // chunks 0, 2 and 3 are in view, so two runs: [0] and [2, 3].
  std::vector<glm::vec3> positions;
  for (float z : {5.0f, -5.0f, 6.0f, 7.0f, -6.0f})
    for (const glm::vec3& p : {glm::vec3(-1, -1, z), glm::vec3(1, -1, z), glm::vec3(0, 1, z)})
      positions.push_back(p);
  const std::vector<TriangleChunk> chunks = triangleChunks(positions, 1);
  std::vector<DrawArraysIndirectCommand> records;
  appendVisibleRuns(chunks, kFrontFace, 9, records);
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0].first, 0u);
  EXPECT_EQ(records[0].count, 3u);
  EXPECT_EQ(records[1].first, 6u);
  EXPECT_EQ(records[1].count, 6u);
  for (const DrawArraysIndirectCommand& r : records) {
    EXPECT_EQ(r.instance_count, 1u);
    EXPECT_EQ(r.base_instance, 9u);
  }
  static_assert(sizeof(DrawArraysIndirectCommand) == 16, "GL's tightly packed record");
}

}  // namespace
}  // namespace gib::rt
