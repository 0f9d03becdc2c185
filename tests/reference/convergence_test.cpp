// Monte Carlo convergence: the RMSE against a high-spp render falls as spp^(−1/2).
#include "metrics/convergence_fit.h"
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace gib::ref {
namespace {

double rmse(const image::Image& a, const image::Image& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.data().size(); ++i) {
    double d = double(a.data()[i]) - b.data()[i];
    sum += d * d;
  }
  return std::sqrt(sum / double(a.data().size()));
}

TEST(Convergence, RmseFallsWithSlopeMinusOneHalf) {
  const scene::Scene cornell = scene::loadScene("cornell");
  RenderSettings high;
  high.width = high.height = 24;
  high.spp = 4096;
  high.seed = 1;  // independent of the renders under test
  const image::Image truth = renderReference(cornell, high).mean;

  // The reference's own noise adds σ²/4096 to each MSE, under 2% of it at 64 spp.
  RenderSettings low = high;
  low.spp = 64;
  low.seed = 2;
  std::map<std::uint32_t, double> error_at_spp;
  renderReference(cornell, low, [&](std::uint32_t spp, const image::Image& mean) {
    error_at_spp[spp] = rmse(mean, truth);
  });
  std::vector<double> log_spp, log_error;
  for (auto [spp, error] : error_at_spp) {
    log_spp.push_back(std::log(double(spp)));
    log_error.push_back(std::log(error));
  }
  ASSERT_EQ(log_spp.size(), 7u);  // 1, 2, 4, …, 64
  metrics::LinearFit fit = metrics::fitLine(log_spp, log_error);
  EXPECT_NEAR(fit.slope, -0.5, 0.1) << "intercept " << fit.intercept;
}

}  // namespace
}  // namespace gib::ref
