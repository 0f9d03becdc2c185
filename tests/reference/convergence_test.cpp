// Convergence: the RMSE against a high-spp render falls as spp^(−1/2) with independent samples,
// and at least as fast with the low-discrepancy sampler.
#include "metrics/convergence_fit.h"
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
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

// The fitted slope of log RMSE against log spp over the checkpoints 1, 2, 4, …, 64 of 24×24
// Cornell boxes, against an independent 4096-spp render (whose own noise adds σ²/4096 to each MSE,
// under 2% of it at 64 spp).
metrics::LinearFit convergenceSlope(SamplerKind sampler, std::uint32_t replicas) {
  const scene::Scene cornell = scene::loadScene("cornell");
  RenderSettings high;
  high.width = high.height = 24;
  high.spp = 4096;
  high.seed = 1;  // independent of the renders under test
  const image::Image truth = renderReference(cornell, high).mean;

  // The MSE of so few pixels is ruled by the light's edge, a coin toss between 17 and 0.7 per
  // independent sample: one render's curve wanders by tens of percent. The mean over eight
  // independent renders steadies it.
  constexpr int kRenders = 8;
  std::map<std::uint32_t, double> mse_at_spp;
  for (int r = 0; r < kRenders; ++r) {
    RenderSettings low = high;
    low.spp = 64;
    low.seed = 2 + std::uint64_t(r);
    low.sampler = sampler;
    low.replicas = replicas;
    renderReference(cornell, low, [&](std::uint32_t spp, const image::Image& mean) {
      const double e = rmse(mean, truth);
      mse_at_spp[spp] += e * e / kRenders;
    });
  }
  std::vector<double> log_spp, log_error;
  for (auto [spp, mse] : mse_at_spp) {
    log_spp.push_back(std::log(double(spp)));
    log_error.push_back(0.5 * std::log(mse));
  }
  EXPECT_EQ(log_spp.size(), 7u);  // 1, 2, 4, …, 64
  return metrics::fitLine(log_spp, log_error);
}

TEST(Convergence, IndependentSamplesFallWithSlopeMinusOneHalf) {
  const metrics::LinearFit fit = convergenceSlope(SamplerKind::kIndependent, 1);
  EXPECT_NEAR(fit.slope, -0.5, 0.1) << "intercept " << fit.intercept;
}

TEST(Convergence, LowDiscrepancySamplesFallAtLeastAsFast) {
  // Monte Carlo's −1/2 is the slowest rate unbiased sampling may show; stratified points do
  // better where the integrand is smooth enough. The bound −1/2 must hold within the slope's 95%
  // confidence interval, for one replica (the sampler alone) and for the default split.
  for (std::uint32_t replicas : {1u, 0u}) {
    const metrics::LinearFit fit = convergenceSlope(SamplerKind::kSobol, replicas);
    EXPECT_LE(fit.slope, -0.5 + fit.slope_ci95) << "replicas " << replicas;
    // And no faster than Owen-scrambled nets allow even for smooth integrands (variance
    // O(n⁻³), RMSE slope −3/2): a faster fall would mean the truth and the test share noise.
    EXPECT_GE(fit.slope, -1.5 - fit.slope_ci95) << "replicas " << replicas;
    std::printf("replicas %u: RMSE slope %.3f ± %.3f (95%%)\n", replicas, fit.slope,
                fit.slope_ci95);
  }
}

}  // namespace
}  // namespace gib::ref
