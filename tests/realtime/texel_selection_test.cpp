// Random texel selection (Barsi & Jakab §3.1, book §7.1.1): both the GPU pyramid descent and the
// CPU read-back search choose texels with probability proportional to their power, by chi-square
// (the seeds are fixed, so a given build either passes or fails every time).
#include "realtime/techniques/stochastic_radiosity/texel_selection.h"

#include "support/gl_test_context.h"
#include "support/statistical_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace gib::rt {
namespace {

using test::GlTest;

// Correct selectors fail one of this file's two chi-square tests (the GPU's, the CPU's) with
// probability 1%.
constexpr test::TestFamily kFamily(0.01, 2);
constexpr int kResolution = 16;
constexpr int kSelections = 40000;

class TexelSelectionTest : public test::GlTest,
                           public ::testing::WithParamInterface<SelectionMethod> {};

// A power map with a fifth of the texels dark and the rest spread over two orders of magnitude.
std::vector<float> randomPowerMap() {
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<float> power(kResolution * kResolution);
  for (float& p : power) p = unit(random) < 0.2f ? 0.0f : std::pow(10.0f, 2.0f * unit(random));
  return power;
}

std::vector<double> selectionCounts(SelectionMethod method, const std::vector<float>& power) {
  TexelSelection selection(method, kResolution, kSelections);
  glTextureSubImage2D(selection.powerMap().id(), 0, 0, 0, kResolution, kResolution, GL_RED,
                      GL_FLOAT, power.data());
  selection.buildPyramid();
  std::mt19937 random(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<float> u(kSelections);
  for (float& v : u) v = unit(random);
  selection.select(u);
  double total = 0;
  for (float p : power) total += p;
  std::vector<double> counts(power.size(), 0.0);
  for (const gpu::Shooter& s : selection.readSelections(kSelections)) {
    const std::size_t i = std::size_t(s.texel.y * kResolution + s.texel.x);
    EXPECT_TRUE(s.texel.x >= 0 && s.texel.y >= 0 && s.texel.x < kResolution &&
                s.texel.y < kResolution);
    if (i >= power.size()) continue;
    EXPECT_EQ(s.power, power[i]) << "the update divides by the power the selection saw";
    EXPECT_NEAR(s.total_power, total, 1e-5 * total);
    counts[i] += 1;
  }
  return counts;
}

TEST_P(TexelSelectionTest, FrequenciesFollowPowerByChiSquare) {
  const std::vector<float> power = randomPowerMap();
  const std::vector<double> observed = selectionCounts(GetParam(), power);
  double total = 0;
  for (float p : power) total += p;
  std::vector<double> expected(power.size());
  for (std::size_t i = 0; i < power.size(); ++i) {
    expected[i] = kSelections * power[i] / total;
    if (power[i] == 0) {
      EXPECT_EQ(observed[i], 0.0) << "texel " << i << " has no power";
    }
  }
  EXPECT_TRUE(kFamily.chiSquare(observed, expected));

  // The test has power: the same counts are far from a uniform choice.
  std::vector<double> uniform(power.size(), double(kSelections) / double(power.size()));
  EXPECT_FALSE(kFamily.chiSquare(observed, uniform));
}

TEST_P(TexelSelectionTest, NothingIsSelectedWhenNothingHasPower) {
  TexelSelection selection(GetParam(), kResolution, 1);
  const std::vector<float> dark(kResolution * kResolution, 0.0f);
  glTextureSubImage2D(selection.powerMap().id(), 0, 0, 0, kResolution, kResolution, GL_RED,
                      GL_FLOAT, dark.data());
  selection.buildPyramid();
  selection.select({0.5f});
  EXPECT_EQ(selection.readSelections(1)[0].texel, glm::ivec2(-1, -1));
}

// The GPU pyramid sums several levels per compute pass (texel_selection.h): every texel of every
// level is the float sum of its four children, what one pass per level computes, up to the order
// in which the shader compiler pairs the three additions (a few ulps), at resolutions of one
// pass (16) and of two and three (128, 1024: a pass's partial top levels).
TEST_F(GlTest, PyramidLevelsAreTheSumsOfTheirFourChildren) {
  std::mt19937 random(3);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (const int resolution : {16, 128, 1024}) {
    TexelSelection selection(SelectionMethod::kGpu, resolution, 1);
    std::vector<float> power(std::size_t(resolution) * std::size_t(resolution));
    for (float& p : power) p = unit(random) < 0.2f ? 0.0f : std::pow(10.0f, 3.0f * unit(random));
    glTextureSubImage2D(selection.powerMap().id(), 0, 0, 0, resolution, resolution, GL_RED,
                        GL_FLOAT, power.data());
    selection.buildPyramid();
    std::vector<float> finer = power;
    for (int level = 1, size = resolution / 2; size >= 1; ++level, size /= 2) {
      std::vector<float> coarser(std::size_t(size) * std::size_t(size), -1.0f);
      glGetTextureImage(selection.powerMap().id(), level, GL_RED, GL_FLOAT,
                        GLsizei(coarser.size() * sizeof(float)), coarser.data());
      const int fine = 2 * size;
      for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
          auto child = [&](int dx, int dy) {
            return finer[std::size_t((2 * y + dy) * fine + 2 * x + dx)];
          };
          const float sum = child(0, 0) + child(1, 0) + child(0, 1) + child(1, 1);
          ASSERT_NEAR(coarser[std::size_t(y * size + x)], sum,
                      4.0f * std::numeric_limits<float>::epsilon() * sum)
              << "resolution " << resolution << ", level " << level << ", texel " << x << "," << y;
        }
      finer = std::move(coarser);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, TexelSelectionTest,
                         ::testing::Values(SelectionMethod::kGpu, SelectionMethod::kCpu),
                         [](const auto& info) {
                           return info.param == SelectionMethod::kGpu ? "gpu" : "cpu";
                         });

}  // namespace
}  // namespace gib::rt
