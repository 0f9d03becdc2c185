// The pixel-centre reference (docs/rendering.md, "Pixel sampling"): the error of an image that
// equals it up to noise is that noise, while against the box-filtered reference the same image
// carries the anti-aliasing difference on every edge; and the choice is named and keyed apart.
#include "common/input_error.h"
#include "reference/progressive_renderer.h"
#include "reference/reference_store.h"
#include "scene/builtin_scenes.h"
#include "support/render_statistics.h"
#include "support/statistical_test.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace gib::ref {
namespace {

constexpr int kSize = 48;
constexpr std::uint32_t kSpp = 64;
constexpr std::uint32_t kReplicas = 8;  // 7 degrees of freedom for each pixel's variance
// A correct renderer fails this file's one statistical test (an image equal to the matched
// reference up to noise has only noise for error) with probability 1%.
constexpr test::TestFamily kFamily(0.01, 1);

RenderResult render(const scene::Scene& scene, PixelSampling sampling, std::uint64_t seed) {
  RenderSettings settings;
  settings.width = settings.height = kSize;
  settings.spp = kSpp;
  settings.replicas = kReplicas;
  settings.seed = seed;
  settings.pixel_sampling = sampling;
  return renderReference(scene, settings);
}

// An independent pixel-centre render stands for a technique whose pixels are the matched
// reference's up to noise. relMSE less both images' noise (an unbiased estimate of the squared
// error against the truth, tests/support/render_statistics.h) is then zero within its standard
// error; against the box-filtered reference it is the anti-aliasing difference, far outside.
TEST(PixelSampling, AnImageEqualToTheMatchedReferenceUpToNoiseHasOnlyNoiseForError) {
  const scene::Scene scene = scene::loadScene("cornell");
  const RenderResult matched = render(scene, PixelSampling::kCenter, 0);
  const RenderResult boxed = render(scene, PixelSampling::kArea, 0);
  const RenderResult test = render(scene, PixelSampling::kCenter, 1234567);

  const test::MeanEstimate against_matched =
      test::relMseLessNoise(matched, test.mean, test.variance);
  const test::MeanEstimate against_boxed = test::relMseLessNoise(boxed, test.mean, test.variance);
  std::printf("relMSE less noise: matched %.5f ± %.5f, box-filtered %.5f ± %.5f\n",
              against_matched.mean, against_matched.standard_error, against_boxed.mean,
              against_boxed.standard_error);
  EXPECT_TRUE(
      kFamily.tTest(against_matched.mean, 0, against_matched.standard_error, against_matched.dof));
  // The same test rejects the box-filtered reference, which the image exceeds.
  EXPECT_GT(against_boxed.mean, 0);
  EXPECT_FALSE(
      kFamily.tTest(against_boxed.mean, 0, against_boxed.standard_error, against_boxed.dof));
}

TEST(PixelSampling, NamesParseBackAndAnUnknownOneIsAnInputError) {
  for (PixelSampling s : {PixelSampling::kArea, PixelSampling::kCenter})
    EXPECT_EQ(parsePixelSampling(pixelSamplingName(s)), s);
  try {
    parsePixelSampling("centre");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("give center"), std::string::npos) << e.what();
  }
}

// A pixel-centre reference has a key of its own; a box-filtered one keeps the key it had before
// the choice existed (the hash of the same fields, nothing added), so stored references stay hits.
TEST(PixelSampling, CentreReferencesAreKeyedApartFromBoxFilteredOnes) {
  const scene::Scene scene = scene::loadScene("cornell");
  ReferenceSpec area;
  area.scene = "cornell";
  ReferenceSpec centre = area;
  centre.pixel_sampling = PixelSampling::kCenter;
  EXPECT_NE(referenceKey(scene, area), referenceKey(scene, centre));
  ReferenceSpec other_seed = area;
  other_seed.seed = 1;
  EXPECT_NE(referenceKey(scene, area), referenceKey(scene, other_seed));
}

}  // namespace
}  // namespace gib::ref
