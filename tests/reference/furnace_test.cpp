// The furnace: every pixel's exact radiance is 1.0 (L = Le / (1 − ρ) with Le = ρ = 0.5).
#include "metrics/distributions.h"
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace gib::ref {
namespace {

struct ImageMean {
  double mean = 0;
  double standard_error = 0;
};

// The mean over all pixels and channels; pixels are independent, so its variance is Σ var / N².
ImageMean imageMean(const RenderResult& r) {
  double sum = 0, sum_variance = 0;
  for (std::size_t i = 0; i < r.mean.data().size(); ++i) {
    sum += r.mean.data()[i];
    sum_variance += r.variance.data()[i];
  }
  const double n = double(r.mean.data().size());
  return {sum / n, std::sqrt(sum_variance) / n};
}

TEST(Furnace, EveryPixelIsOneWithinItsStandardError) {
  const scene::Scene furnace = scene::loadScene("furnace");
  RenderSettings settings;
  settings.width = settings.height = 16;
  settings.spp = 256;
  const RenderResult r = renderReference(furnace, settings);

  // Per pixel and channel, a two-sided Z-test. With 768 tests, a family-wise significance of 1%
  // under the Šidák correction needs |z| below ~4.2; the 3-standard-error bound would
  // fail by chance on ~2 pixels, so it is applied to the image mean instead (below).
  const double tests = 3.0 * r.mean.pixelCount();
  const double z_max = metrics::normalQuantile(1 - metrics::sidakSignificance(0.01, tests) / 2);
  for (std::size_t i = 0; i < r.mean.data().size(); ++i) {
    double variance = r.variance.data()[i];
    ASSERT_GT(variance, 0.0) << "the estimator is not deterministic here";
    EXPECT_LT(std::abs(r.mean.data()[i] - 1.0), z_max * std::sqrt(variance)) << "value " << i;
  }
  const ImageMean m = imageMean(r);
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
    const ImageMean m = imageMean(renderReference(furnace, settings));
    const double expected = 1.0 - std::pow(0.5, k + 1);
    EXPECT_NEAR(m.mean, expected, 3 * m.standard_error + 1e-6) << "k = " << k;
  }
}

}  // namespace
}  // namespace gib::ref
