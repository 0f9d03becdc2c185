// Same inputs → bit-identical images, whatever the thread count (docs/architecture.md,
// "Randomness").
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"

#include <gtest/gtest.h>

#include <cstring>

namespace gib::ref {
namespace {

bool bitIdentical(const image::Image& a, const image::Image& b) {
  return a.sameSize(b) && std::memcmp(a.data().data(), b.data().data(), a.data().size_bytes()) == 0;
}

TEST(Determinism, ImagesAreBitIdenticalAcrossThreadCounts) {
  const scene::Scene cornell = scene::loadScene("cornell");
  RenderSettings settings;
  settings.width = 40;
  settings.height = 24;  // not a multiple of the tile size
  settings.spp = 8;
  settings.threads = 1;
  const RenderResult one = renderReference(cornell, settings);
  settings.threads = 2;
  const RenderResult two = renderReference(cornell, settings);
  EXPECT_TRUE(bitIdentical(one.mean, two.mean));
  EXPECT_TRUE(bitIdentical(one.variance, two.variance));
  EXPECT_TRUE(bitIdentical(one.direct, two.direct));
  EXPECT_TRUE(bitIdentical(one.indirect, two.indirect));
  EXPECT_EQ(one.rays, two.rays);
}

TEST(Determinism, SeedChangesTheNoise) {
  const scene::Scene cornell = scene::loadScene("cornell");
  RenderSettings settings;
  settings.width = settings.height = 16;
  settings.spp = 2;
  const RenderResult a = renderReference(cornell, settings);
  settings.seed = 7;
  const RenderResult b = renderReference(cornell, settings);
  EXPECT_FALSE(bitIdentical(a.mean, b.mean));
}

TEST(Determinism, DirectPlusIndirectIsTheTotal) {
  const scene::Scene cornell = scene::loadScene("cornell");
  RenderSettings settings;
  settings.width = settings.height = 16;
  settings.spp = 4;
  const RenderResult r = renderReference(cornell, settings);
  double direct = 0, indirect = 0;
  for (std::size_t i = 0; i < r.mean.data().size(); ++i) {
    EXPECT_NEAR(r.direct.data()[i] + r.indirect.data()[i], r.mean.data()[i],
                1e-5f * (1 + r.mean.data()[i]));
    direct += r.direct.data()[i];
    indirect += r.indirect.data()[i];
  }
  // In the Cornell box both parts carry a visible share of the light.
  EXPECT_GT(direct, 0);
  EXPECT_GT(indirect, 0.1 * direct);
}

}  // namespace
}  // namespace gib::ref
