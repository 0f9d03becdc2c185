// The reference's error bars are calibrated: the variance layer (from the spread of independently
// scrambled replicas) says how far a pixel may be from the truth, and it is right as often as
// its distribution says. Checked on a scene with a known answer (the furnace: every pixel is
// exactly 1) and on the Cornell box against a render four times longer (whose own error is in
// the statistic). Each count of pixels beyond a bound is tested against its binomial
// distribution.
#include "metrics/z_test.h"
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"
#include "support/statistical_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace gib::ref {
namespace {

// Calibrated error bars fail one of this file's four binomial tests (two tails, each in the
// furnace and the Cornell box) with probability 1%.
constexpr test::TestFamily kFamily(0.01, 4);

// The normal's two-sided tail beyond ±2 and ±3 standard errors: the fractions of pixels a
// calibrated error bar leaves outside, once each statistic is mapped to the normal through its
// own distribution (its p-value).
constexpr double kBeyondTwo = 0.045500263896358;
constexpr double kBeyondThree = 0.002699796063260;

// Counts the values whose p-value is below each bound, and tests both counts.
void expectCalibrated(const std::vector<double>& p_values, const char* what) {
  for (double bound : {kBeyondTwo, kBeyondThree}) {
    std::size_t beyond = 0;
    for (double p : p_values) beyond += p < bound;
    const ::testing::AssertionResult calibrated = kFamily.binomial(beyond, p_values.size(), bound);
    EXPECT_TRUE(calibrated) << what;
    std::printf("%s: %s\n", what, calibrated.message());
  }
}

TEST(ErrorBarCalibration, FurnacePixelsMissTheTruthAsOftenAsTheirErrorBarsSay) {
  const scene::Scene furnace = scene::loadScene("furnace");
  RenderSettings settings;
  settings.width = settings.height = 48;
  // 4 replicas (the default) of 1024 samples. Far fewer samples do not do: the furnace's paths
  // are skewed
  // (skewness 4.7 per sample, from Russian roulette's rare survivors), and a replica mean that
  // missed the rare long paths has both a low mean and a low spread, so at 256 spp 5-9 times too
  // many pixels fall beyond 3 standard errors, on the low side (docs/rendering.md, "Error bars").
  settings.spp = 4096;
  const RenderResult r = renderReference(furnace, settings);
  // One channel: the furnace is grey, so a pixel's three channels are one value.
  std::vector<double> p_values;
  for (std::size_t i = 0; i < r.mean.pixelCount(); ++i)
    p_values.push_back(metrics::differencePValue(
        r.mean.data()[3 * i] - 1.0, r.variance.data()[3 * i], r.variance_dof, 0.0, 0.0));
  expectCalibrated(p_values, "furnace");

  // Read as a normal standard error, the same variance leaves too many pixels outside ±3
  // (Student's t₃ puts 5.8% there, not 0.27%): the degrees of freedom are part of the error bar.
  std::size_t beyond_three = 0;
  for (std::size_t i = 0; i < r.mean.pixelCount(); ++i)
    beyond_three += std::abs(r.mean.data()[3 * i] - 1.0) > 3 * std::sqrt(r.variance.data()[3 * i]);
  EXPECT_FALSE(kFamily.binomial(beyond_three, r.mean.pixelCount(), kBeyondThree))
      << "beyond ±3 standard errors";
}

TEST(ErrorBarCalibration, CornellPixelsMissALongerRenderAsOftenAsTheirErrorBarsSay) {
  const scene::Scene cornell = scene::loadScene("cornell");
  RenderSettings truth_settings;
  truth_settings.width = 48;
  truth_settings.height = 36;
  truth_settings.spp = 4096;
  truth_settings.seed = 1;
  const RenderResult truth = renderReference(cornell, truth_settings);
  RenderSettings settings = truth_settings;
  settings.spp = 1024;
  settings.seed = 2;
  const RenderResult r = renderReference(cornell, settings);
  // One channel (green), so the values are independent; the longer render's own variance is in
  // the test's.
  std::vector<double> p_values;
  for (std::size_t i = 0; i < r.mean.pixelCount(); ++i) {
    const std::size_t g = 3 * i + 1;
    if (r.variance.data()[g] + truth.variance.data()[g] <= 0) continue;
    p_values.push_back(metrics::differencePValue(r.mean.data()[g] - truth.mean.data()[g],
                                                 r.variance.data()[g], r.variance_dof,
                                                 truth.variance.data()[g], truth.variance_dof));
  }
  // A quarter of the image looks out of the open box at nothing: zero variance, not tested.
  EXPECT_GT(p_values.size(), 1200u);
  expectCalibrated(p_values, "cornell");
}

}  // namespace
}  // namespace gib::ref
