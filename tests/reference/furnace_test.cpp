// The furnace: every pixel's exact radiance is 1.0 (L = Le / (1 − ρ) with Le = ρ = 0.5).
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"
#include "support/render_statistics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace gib::ref {
namespace {

using test::imageMean;

TEST(Furnace, EveryPixelIsOneWithinItsStandardError) {
  const scene::Scene furnace = scene::loadScene("furnace");
  RenderSettings settings;
  settings.width = settings.height = 16;
  settings.spp = 256;
  // 8 replicas rather than the default 4: with 7 degrees of freedom the per-value bound below is
  // ~11 standard errors; with 3 it would be ~70, which tests little.
  settings.replicas = 8;
  const RenderResult r = renderReference(furnace, settings);

  // Per pixel and channel, a two-sided test of (mean − 1)/standard error, which follows Student's
  // t with the replicas' degrees of freedom (7 here). With 768 tests, a family-wise significance
  // of 1% under the Šidák correction needs |t| below ~10.8; a 3-standard-error bound would fail
  // by chance on ~15 values, so it is applied to the image mean instead (below).
  ASSERT_EQ(r.variance_dof, 7u);
  const double tests = 3.0 * r.mean.pixelCount();
  const double t_max = test::familyWiseBound(r, tests, 0.01);
  for (std::size_t i = 0; i < r.mean.data().size(); ++i) {
    double variance = r.variance.data()[i];
    ASSERT_GT(variance, 0.0) << "the estimator is not deterministic here";
    EXPECT_LT(std::abs(r.mean.data()[i] - 1.0), t_max * std::sqrt(variance)) << "value " << i;
  }
  const test::ImageMean m = imageMean(r);
  EXPECT_NEAR(m.mean, 1.0, 3 * m.standard_error) << "± " << m.standard_error;
  EXPECT_LT(m.standard_error, 0.01);
}

TEST(Furnace, BounceLimitedRadianceIsTheGeometricSeries) {
  // With at most k bounces, L = Σ_{j=0..k} ρʲ·Le = 0.5·(1 − 0.5^{k+1}) / 0.5 = 1 − 0.5^{k+1}.
  const scene::Scene furnace = scene::loadScene("furnace");
  for (int k : {0, 1, 3}) {
    RenderSettings settings;
    settings.width = settings.height = 8;
    settings.spp = 256;
    settings.path_class.max_bounces = k;
    const test::ImageMean m = imageMean(renderReference(furnace, settings));
    const double expected = 1.0 - std::pow(0.5, k + 1);
    EXPECT_NEAR(m.mean, expected, 3 * m.standard_error + 1e-6) << "k = " << k;
  }
}

}  // namespace
}  // namespace gib::ref
