// The reference's sampler: stratification of its points (every power-of-two prefix of a pixel's
// samples is a (0,m,2)-net in each 2D dimension), uniformity and independence by chi-square,
// independence of replicas, determinism.
#include "reference/path_sampler.h"
#include "support/statistical_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

namespace gib::ref {
namespace {

// A correct sampler fails one of this file's six statistical tests (five chi-square tests of
// uniformity, the replicas' correlation) with probability 1%.
constexpr test::TestFamily kFamily(0.01, 6);

// The 2D points of dimension `d` of vertex `vertex` for samples first, first + step, … (n of
// them) of `pixel`.
std::vector<glm::vec2> points(std::uint32_t pixel, int vertex, VertexDimension d, std::uint32_t n,
                              std::uint32_t replicas = 1, std::uint32_t replica = 0) {
  std::vector<glm::vec2> out;
  for (std::uint32_t j = 0; j < n; ++j) {
    PathSampler sampler(7, pixel, replica + j * replicas, replicas);
    sampler.startVertex(vertex);
    out.push_back(sampler.get2D(d));
  }
  return out;
}

// True when the 2^m points are a (0,m,2)-net in base 2: for every split of m into a + b, each
// 2^-a × 2^-b box holds exactly one point.
bool isZeroNet(const std::vector<glm::vec2>& p, int m) {
  for (int a = 0; a <= m; ++a) {
    const int b = m - a;
    std::set<std::pair<int, int>> cells;
    for (const glm::vec2& q : p)
      cells.insert({int(std::ldexp(double(q.x), a)), int(std::ldexp(double(q.y), b))});
    if (cells.size() != p.size()) return false;
  }
  return true;
}

TEST(PathSampler, EveryPowerOfTwoPrefixIsAZeroNetInEachDimensionPair) {
  const VertexDimension dims[] = {VertexDimension::kLightPoint, VertexDimension::kSkyDirection,
                                  VertexDimension::kDirection};
  for (std::uint32_t pixel : {0u, 1u, 4097u})
    for (int vertex : {0, 1, 7}) {
      for (VertexDimension d : dims) {
        const std::vector<glm::vec2> p = points(pixel, vertex, d, 1024);
        for (int m = 0; m <= 10; ++m)
          EXPECT_TRUE(isZeroNet({p.begin(), p.begin() + (1 << m)}, m))
              << "pixel " << pixel << " vertex " << vertex << " dimension " << int(d) << " m " << m;
      }
    }
  // The pixel position too, and each replica's own samples when the render is split.
  for (std::uint32_t replica : {0u, 5u, 15u}) {
    std::vector<glm::vec2> p;
    for (std::uint32_t j = 0; j < 256; ++j)
      p.push_back(PathSampler(7, 3, replica + 16 * j, 16).pixelPosition());
    for (int m = 0; m <= 8; ++m)
      EXPECT_TRUE(isZeroNet({p.begin(), p.begin() + (1 << m)}, m)) << "replica " << replica;
  }
}

TEST(PathSampler, OneDimensionalDecisionsAreStratified) {
  for (VertexDimension d : {VertexDimension::kLightShadow, VertexDimension::kRoulette}) {
    std::vector<float> u;
    for (std::uint32_t s = 0; s < 512; ++s) {
      PathSampler sampler(3, 11, s, 1);
      sampler.startVertex(2);
      u.push_back(sampler.get1D(d));
    }
    for (int m = 0; m <= 9; ++m) {
      std::set<int> strata;
      for (int i = 0; i < (1 << m); ++i) strata.insert(int(std::ldexp(double(u[i]), m)));
      EXPECT_EQ(strata.size(), std::size_t(1) << m) << "dimension " << int(d) << " m " << m;
    }
  }
}

// Counts of 2D values on a 16 × 16 grid, by chi-square against uniform.
::testing::AssertionResult uniform(const std::vector<glm::vec2>& values) {
  constexpr int kCells = 16;
  std::vector<double> observed(kCells * kCells, 0.0);
  for (const glm::vec2& v : values) {
    EXPECT_TRUE(v.x >= 0 && v.x < 1 && v.y >= 0 && v.y < 1);
    observed[std::size_t(int(v.y * kCells) * kCells + int(v.x * kCells))] += 1;
  }
  const std::vector<double> expected(observed.size(), double(values.size()) / observed.size());
  return kFamily.chiSquare(observed, expected);
}

TEST(PathSampler, PointsAreUniformOverPixelsAndDimensionsAreIndependent) {
  // Over 2^16 pixels (independent scrambles), one sample's point of one dimension is uniform in
  // the square; so are two different dimensions' first coordinates taken together, which they
  // would not be if the padding correlated them.
  std::vector<glm::vec2> same_dimension, across_dimensions, across_vertices;
  for (std::uint32_t pixel = 0; pixel < 65536; ++pixel) {
    PathSampler sampler(1, pixel, 5, 1);
    sampler.startVertex(0);
    same_dimension.push_back(sampler.get2D(VertexDimension::kDirection));
    const float light = sampler.get1D(VertexDimension::kLightPoint);
    across_dimensions.push_back({light, sampler.get1D(VertexDimension::kDirection)});
    sampler.startVertex(1);
    across_vertices.push_back({light, sampler.get1D(VertexDimension::kLightPoint)});
  }
  EXPECT_TRUE(uniform(same_dimension));
  EXPECT_TRUE(uniform(across_dimensions));
  EXPECT_TRUE(uniform(across_vertices));
}

TEST(PathSampler, ReplicasAreIndependent) {
  // Replica 0's and replica 1's first points of a pixel, over many pixels: jointly uniform in the
  // unit square (their x coordinates), with no correlation between them.
  std::vector<glm::vec2> pairs;
  double sxy = 0;
  for (std::uint32_t pixel = 0; pixel < 65536; ++pixel) {
    const float a = PathSampler(2, pixel, 0, 8).pixelPosition().x;
    const float b = PathSampler(2, pixel, 1, 8).pixelPosition().x;
    pairs.push_back({a, b});
    sxy += (a - 0.5) * (b - 0.5);
  }
  EXPECT_TRUE(uniform(pairs));
  // The correlation coefficient: zero, with standard deviation 1/√n under independence.
  const double correlation = (sxy / 65536.0) / (1.0 / 12.0);
  EXPECT_TRUE(kFamily.zTest(correlation, 0.0, 1 / std::sqrt(65536.0)));
}

TEST(PathSampler, IndependentSamplerIsUniformButNotStratified) {
  std::vector<glm::vec2> p;
  for (std::uint32_t s = 0; s < 65536; ++s)
    p.push_back(PathSampler(4, 9, s, 1, SamplerKind::kIndependent).pixelPosition());
  EXPECT_TRUE(uniform(p));
  // 256 independent points fill a 16 × 16 grid's cells one each with vanishing probability.
  EXPECT_FALSE(isZeroNet({p.begin(), p.begin() + 256}, 8));
}

TEST(PathSampler, PointsArePureFunctionsOfSeedPixelSampleAndDimension) {
  PathSampler a(5, 17, 33, 4), b(5, 17, 33, 4), other_seed(6, 17, 33, 4);
  a.startVertex(3);
  b.startVertex(0);
  b.startVertex(3);  // what was drawn before does not matter
  other_seed.startVertex(3);
  EXPECT_EQ(a.get2D(VertexDimension::kDirection), b.get2D(VertexDimension::kDirection));
  EXPECT_EQ(a.get1D(VertexDimension::kRoulette), b.get1D(VertexDimension::kRoulette));
  EXPECT_NE(a.get2D(VertexDimension::kDirection), other_seed.get2D(VertexDimension::kDirection));
}

}  // namespace
}  // namespace gib::ref
