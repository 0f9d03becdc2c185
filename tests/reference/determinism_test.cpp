// Same inputs → bit-identical images, whatever the thread count (docs/architecture.md,
// "Randomness").
#include "reference/embree_scene.h"
#include "reference/path_sampler.h"
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <span>
#include <vector>

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

TEST(Determinism, CameraRayBatchesHitExactlyWhatSingleRaysHit) {
  // The renderer traces a pixel's camera rays as one coherent batch (Embree packets); the image
  // is independent of how samples fall into batches only if every ray's hit is bit-identical to
  // the single-ray query. Rays through every pixel of a 64×48 Cornell box image, 64 jittered
  // positions each, in batches of 64, 7 (ragged packets) and 1.
  const scene::Scene cornell = scene::loadScene("cornell");
  const EmbreeScene embree(cornell);
  constexpr int kWidth = 64, kHeight = 48, kPerPixel = 64;
  const scene::CameraFrame camera = scene::makeCameraFrame(cornell.camera, kWidth, kHeight);
  std::vector<scene::Ray> rays;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      for (std::uint32_t s = 0; s < kPerPixel; ++s) {
        PathSampler sampler(3, std::uint32_t(y * kWidth + x), s, 1);
        const glm::vec2 p = glm::vec2(x, y) + sampler.pixelPosition();
        rays.push_back(
            {camera.origin, scene::cameraRayDirection(camera, kWidth, kHeight, p.x, p.y)});
      }
  for (std::size_t batch : {std::size_t(kPerPixel), std::size_t(7), std::size_t(1)}) {
    std::size_t mismatches = 0;
    for (std::size_t first = 0; first < rays.size(); first += batch) {
      const std::size_t n = std::min(batch, rays.size() - first);
      std::vector<Hit> hits(n);
      embree.intersect(std::span(rays).subspan(first, n), hits, /*coherent=*/true);
      for (std::size_t i = 0; i < n; ++i) {
        const Hit single = embree.intersect(rays[first + i].origin, rays[first + i].direction);
        mismatches += std::memcmp(&single.t, &hits[i].t, sizeof(float)) != 0 ||
                      single.mesh != hits[i].mesh || single.triangle != hits[i].triangle;
      }
    }
    EXPECT_EQ(mismatches, 0u) << "batches of " << batch << ", " << rays.size() << " rays";
  }
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
