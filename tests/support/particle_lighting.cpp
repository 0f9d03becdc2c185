#include "support/particle_lighting.h"

#include "metrics/image_metrics.h"
#include "realtime/particles/particle_shared.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace gib::test {

double ownDepthPerTauR() {
  // D(b) for τ = r = 1 by its closed form; the midpoint rule over b ∈ [0, 1] with weight 2πb.
  constexpr int kSteps = 4096;
  double depth_squared = 0, depth = 0;
  for (int i = 0; i < kSteps; ++i) {
    const double b = (i + 0.5) / kSteps;
    const double d = rt::gpu::chordOpticalDepth(1.0f, 1.0f, float(b), -2.0f, 2.0f);
    depth_squared += d * d * b;
    depth += d * b;
  }
  return 0.5 * depth_squared / depth;
}

CentreLightingAllowance centreLightingAllowance(
    const std::vector<scene::MediumParticle>& particles) {
  const double per_tau_r = ownDepthPerTauR();
  CentreLightingAllowance allowance;
  double mass = 0;
  for (const scene::MediumParticle& p : particles) {
    const double a = per_tau_r * p.density * p.radius;
    const double m = double(p.density) * p.radius * p.radius * p.radius;
    allowance.mean += m * (a + a * a);
    allowance.largest = std::max(allowance.largest, a + a * a);
    mass += m;
  }
  allowance.mean /= mass;
  return allowance;
}

ScatteredLightMatch matchScatteredLight(const ref::RenderResult& reference,
                                        const image::Image& image, const image::Image& transmitted,
                                        const CentreLightingAllowance& allowance) {
  metrics::requireComparable(reference.mean, image);
  metrics::requireComparable(reference.mean, transmitted);
  image::Image scattered = reference.mean;  // the reference's scattered light
  for (std::size_t i = 0; i < scattered.data().size(); ++i)
    scattered.data()[i] -= transmitted.data()[i];
  const ImageMean total = imageMean(reference);
  const double technique = imageMean(image) - imageMean(transmitted);
  const double truth = imageMean(scattered);
  ScatteredLightMatch match;
  match.ratio = {technique / truth, technique / truth * total.standard_error / truth, total.dof};
  match.relmse = relMseLessNoise(reference, image);
  match.relmse_allowance = relMseOfRelativeError(reference.mean, scattered, allowance.largest);
  return match;
}

void expectScatteredLightMatches(const ScatteredLightMatch& match,
                                 const CentreLightingAllowance& allowance,
                                 const TestFamily& family) {
  EXPECT_TRUE(family.tTest(match.ratio.mean, 1.0, match.ratio.standard_error, match.ratio.dof,
                           allowance.mean))
      << "scattered light against the reference's";
  const double k_relmse = family.criticalValue(match.relmse.dof);
  EXPECT_LT(match.relmse.mean, match.relmse_allowance + k_relmse * match.relmse.standard_error)
      << "relMSE less the reference's noise (standard error " << match.relmse.standard_error
      << ", allowance " << match.relmse_allowance << ")";
}

}  // namespace gib::test
