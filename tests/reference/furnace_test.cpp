// The furnace: every pixel's exact radiance is 1.0 (L = Le / (1 − ρ) with Le = ρ = 0.5).
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"
#include "support/render_statistics.h"
#include "support/statistical_test.h"

#include <gtest/gtest.h>

#include <cmath>

namespace gib::ref {
namespace {

using test::imageMean;

constexpr int kSize = 16;  // pixels across the furnace render whose every value is tested
constexpr int kBounceLimits = 3;

// A correct renderer fails one of this file's statistical tests with probability 1%: each value
// of the furnace render and its image mean, and the image mean at each bounce limit.
constexpr test::TestFamily kFamily(0.01, 3 * kSize * kSize + 1 + kBounceLimits);

TEST(Furnace, EveryPixelIsOneWithinItsStandardError) {
  const scene::Scene furnace = scene::loadScene("furnace");
  RenderSettings settings;
  settings.width = settings.height = kSize;
  settings.spp = 256;
  // 8 replicas rather than the default 4: with 7 degrees of freedom the per-value bound below is
  // ~11 standard errors; with 3 it would be ~70, which tests little.
  settings.replicas = 8;
  const RenderResult r = renderReference(furnace, settings);

  // Per pixel and channel, a two-sided test of (mean − 1)/standard error, which follows Student's
  // t with the replicas' degrees of freedom (7 here): with the family's 772 tests, |t| below
  // ~10.8. The image mean's statistic, over many more degrees of freedom, is held far closer.
  ASSERT_EQ(r.variance_dof, 7u);
  for (std::size_t i = 0; i < r.mean.data().size(); ++i) {
    double variance = r.variance.data()[i];
    ASSERT_GT(variance, 0.0) << "the estimator is not deterministic here";
    EXPECT_TRUE(kFamily.tTest(r.mean.data()[i], 1.0, std::sqrt(variance), r.variance_dof))
        << "value " << i;
  }
  const test::ImageMean m = imageMean(r);
  EXPECT_TRUE(kFamily.tTest(m.mean, 1.0, m.standard_error, m.dof));
  EXPECT_LT(m.standard_error, 0.01);
}

TEST(Furnace, BounceLimitedRadianceIsTheGeometricSeries) {
  // With at most k bounces, L = Σ_{j=0..k} ρʲ·Le = 0.5·(1 − 0.5^{k+1}) / 0.5 = 1 − 0.5^{k+1}.
  const scene::Scene furnace = scene::loadScene("furnace");
  for (int k : {0, 1, 3}) {  // kBounceLimits of them
    RenderSettings settings;
    settings.width = settings.height = 8;
    settings.spp = 256;
    settings.path_class.max_bounces = k;
    const test::ImageMean m = imageMean(renderReference(furnace, settings));
    const double expected = 1.0 - std::pow(0.5, k + 1);
    // 1e-6 for float rounding: with no bounce (k = 0) the estimate has no noise.
    EXPECT_TRUE(kFamily.tTest(m.mean, expected, m.standard_error, m.dof, 1e-6)) << "k = " << k;
  }
}

}  // namespace
}  // namespace gib::ref
