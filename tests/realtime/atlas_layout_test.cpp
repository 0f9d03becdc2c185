// The shared texture atlas on the CPU: every surface is covered with exactly its area, texels go
// to surfaces in proportion to their area, and a bilinear lookup anywhere on a surface reads only
// texels of that surface's own chart (no bleeding of black or of a neighbour's light).
#include "realtime/atlas/atlas_layout.h"

#include "common/input_error.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <random>

namespace gib::rt::atlas {
namespace {

struct BakedAtlas {
  std::vector<AtlasTriangle> triangles;
  AtlasLayout layout;
  AtlasTexels texels;
};

BakedAtlas bake(const scene::Scene& scene, int resolution) {
  BakedAtlas a;
  a.triangles = atlasTriangles(scene);
  a.layout = layoutAtlas(a.triangles, resolution);
  a.texels = bakeAtlasTexels(a.triangles, a.layout);
  return a;
}

TEST(AtlasLayout, TexelAreasSumToEverySurfacesArea) {
  const scene::Scene cornell = scene::loadScene("cornell", {});
  for (int resolution : {64, 128, 512}) {
    const BakedAtlas a = bake(cornell, resolution);
    // Per mesh: the texels whose largest share is one of its triangles carry its area, up to
    // texels shared with a neighbouring chart's triangle (none: charts do not share texels).
    std::vector<double> mesh_area(cornell.meshes.size(), 0.0),
        texel_area(cornell.meshes.size(), 0.0);
    for (const AtlasTriangle& t : a.triangles) mesh_area[t.mesh] += t.area;
    for (const AtlasTexel& texel : a.texels.texels)
      if (texel.inChart()) texel_area[a.triangles[std::size_t(texel.triangle)].mesh] += texel.area;
    for (std::size_t m = 0; m < mesh_area.size(); ++m)
      EXPECT_NEAR(texel_area[m], mesh_area[m], 1e-4 * mesh_area[m])
          << cornell.meshes[m].name << " at " << resolution;
  }
}

TEST(AtlasLayout, TexelsAreGivenInProportionToArea) {
  const scene::Scene cornell = scene::loadScene("cornell", {});
  const BakedAtlas a = bake(cornell, 256);
  const double s = a.layout.texels_per_unit;
  std::vector<double> area_texels(cornell.meshes.size(), 0.0),
      edge_texels(cornell.meshes.size(), 0.0);
  std::vector<double> covered(cornell.meshes.size(), 0.0);
  for (const AtlasTriangle& t : a.triangles) {
    area_texels[t.mesh] += t.area * s * s;
    for (int e = 0; e < 3; ++e)
      edge_texels[t.mesh] += glm::length(t.p[(e + 1) % 3] - t.p[e]) * s + 2;
  }
  for (const AtlasTexel& texel : a.texels.texels)
    if (texel.area > 0) covered[a.triangles[std::size_t(texel.triangle)].mesh] += 1;
  // One scale for the whole scene: a texel holds at most 1/s² of area, so a surface needs at
  // least area·s² texels, and at most that plus the texels its edges cross.
  for (std::size_t m = 0; m < covered.size(); ++m) {
    EXPECT_GE(covered[m], std::floor(area_texels[m])) << cornell.meshes[m].name;
    EXPECT_LE(covered[m], area_texels[m] + edge_texels[m]) << cornell.meshes[m].name;
  }
  // And the packing uses the atlas: at least a third of it is surface.
  EXPECT_GT(a.texels.covered, 256 * 256 / 3);
}

// A bilinear lookup at texel coordinate t reads texels floor(t − ½) and the next one per axis.
// At random points inside every triangle, all four must belong to the triangle's chart.
TEST(AtlasLayout, BilinearLookupsInsideASurfaceReadOnlyItsChart) {
  const scene::Scene cornell = scene::loadScene("cornell", {});
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int resolution : {64, 128}) {
    const BakedAtlas a = bake(cornell, resolution);
    for (std::size_t t = 0; t < a.triangles.size(); ++t) {
      const int chart = a.layout.chart_of_triangle[t];
      const auto& uv = a.layout.texel_coordinates[t];
      for (int s = 0; s < 200; ++s) {
        float b1 = unit(random), b2 = unit(random);
        if (b1 + b2 > 1) b1 = 1 - b1, b2 = 1 - b2;
        const glm::vec2 p = uv[0] + b1 * (uv[1] - uv[0]) + b2 * (uv[2] - uv[0]);
        const glm::ivec2 base(int(std::floor(p.x - 0.5f)), int(std::floor(p.y - 0.5f)));
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx) {
            const int x = base.x + dx, y = base.y + dy;
            ASSERT_TRUE(x >= 0 && y >= 0 && x < resolution && y < resolution);
            const AtlasTexel& texel = a.texels.texels[std::size_t(y * resolution + x)];
            ASSERT_TRUE(texel.inChart()) << "triangle " << t << " reads an empty texel";
            EXPECT_EQ(a.layout.chart_of_triangle[std::size_t(texel.triangle)], chart)
                << "triangle " << t << " reads another chart's texel at " << resolution;
          }
      }
    }
  }
}

TEST(AtlasLayout, SamplePointsLieOnTheirSurfaces) {
  const scene::Scene cornell = scene::loadScene("cornell", {});
  const BakedAtlas a = bake(cornell, 128);
  // A texel straddling the fold of a slightly bent quad (the left wall, one chart) has its sample
  // point between the two triangles' planes: within 1e-4 of the scene's size (0.1 mm of 550 mm).
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const AtlasTriangle& t : a.triangles)
    for (const glm::vec3& q : t.p) lo = glm::min(lo, q), hi = glm::max(hi, q);
  const float tolerance = 1e-4f * glm::length(hi - lo);
  for (const AtlasTexel& texel : a.texels.texels) {
    if (!texel.inChart()) continue;
    const AtlasTriangle& t = a.triangles[std::size_t(texel.triangle)];
    EXPECT_NEAR(glm::dot(t.normal, texel.position - t.p[0]), 0.0f, tolerance);
    EXPECT_NEAR(glm::dot(t.normal, texel.normal), 1.0f, 1e-3f);
  }
}

TEST(AtlasLayout, CoplanarTrianglesOfAQuadShareOneChart) {
  const scene::Scene cornell = scene::loadScene("cornell", {});
  const BakedAtlas a = bake(cornell, 128);
  // The floor is one quad: two triangles, one chart.
  for (std::size_t m = 0; m < cornell.meshes.size(); ++m)
    if (cornell.meshes[m].name == "floor") {
      std::vector<int> charts;
      for (std::size_t t = 0; t < a.triangles.size(); ++t)
        if (a.triangles[t].mesh == m) charts.push_back(a.layout.chart_of_triangle[t]);
      ASSERT_EQ(charts.size(), 2u);
      EXPECT_EQ(charts[0], charts[1]);
    }
}

TEST(AtlasLayout, TooManyChartsForTheAtlasIsAnInputError) {
  scene::Scene s;
  s.materials.push_back({});
  scene::Mesh mesh;
  // 1000 separate triangles: each chart needs at least 3 × 3 texels with its gutter.
  for (int i = 0; i < 1000; ++i) {
    const glm::vec3 o(float(i), 0.0f, 0.0f);
    const std::uint32_t base = std::uint32_t(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(),
                          {o, o + glm::vec3(0.5f, 0, 0), o + glm::vec3(0, 0.5f, 0)});
    mesh.triangles.push_back({base, base + 1, base + 2});
  }
  s.meshes.push_back(mesh);
  const std::vector<AtlasTriangle> triangles = atlasTriangles(s);
  try {
    layoutAtlas(triangles, 64);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("larger atlas"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(layoutAtlas(triangles, 256));
}

}  // namespace
}  // namespace gib::rt::atlas
