// Volumetric ground truth: free-flight sampling and transmittance against the exact optical depth
// of the particles' linear fall-off, Henyey–Greenstein sampling (chi-square), the volumetric
// furnace, and path classes in the medium.
#include "reference/medium_tracking.h"
#include "reference/phase_function.h"
#include "reference/progressive_renderer.h"
#include "support/render_statistics.h"
#include "support/statistical_test.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>

namespace gib::ref {
namespace {

constexpr int kFurnaceSize = 12;    // pixels across the volumetric furnace's renders
constexpr int kFurnaceRenders = 4;  // two asymmetries, each seen from two eyes

// A correct renderer fails one of this file's statistical tests with probability 1%: two for
// each of the four chords' transmittance, one chi-square for each of the five asymmetries, every
// value and the image mean of each volumetric furnace render, and the direct layer against single
// scattering.
constexpr test::TestFamily kFamily(0.01,
                                   4 * 2 + 5 +
                                       kFurnaceRenders * (3 * kFurnaceSize * kFurnaceSize + 1) + 1);

// Optical depth of a chord at distance b from the centre of a particle of radius r and density
// τ with linear fall-off: ∫ τ(1 − √(b² + s²)/r) ds over |s| ≤ h = √(r² − b²)
// = τ·(h − (b²/r)·ln((h + r)/b)), and τ·r through the centre.
double chordOpticalDepth(double tau, double r, double b) {
  if (b >= r) return 0;
  const double h = std::sqrt(r * r - b * b);
  return b > 0 ? tau * (h - b * b / r * std::log((h + r) / b)) : tau * r;
}

struct Chord {
  double offset;  // b
  double expected_transmittance;
};

class Transmittance : public ::testing::TestWithParam<double> {};

TEST_P(Transmittance, RatioAndDeltaTrackingMatchBeerLambert) {
  // Two overlapping particles: their optical depths add (the grid must find both).
  const double b = GetParam();
  std::vector<scene::MediumParticle> particles = {{{0, 0, 0}, 1.0f, 2.0f},
                                                  {{0.3f, 0, 0}, 0.8f, 1.5f}};
  const scene::DensityGrid grid(particles);
  const MediumTracker tracker(grid);
  const double depth = chordOpticalDepth(2.0, 1.0, b) + chordOpticalDepth(1.5, 0.8, std::abs(b));
  const double expected = std::exp(-depth);
  // A ray along x at height b, from outside to outside.
  const glm::vec3 origin(-3, float(b), 0), direction(1, 0, 0);

  constexpr int kSamples = 200000;
  double sum = 0, sum_squares = 0;
  int escaped = 0;
  for (int s = 0; s < kSamples; ++s) {
    SampleStream random(17, std::uint32_t(b * 1000), std::uint32_t(s));
    const double t = tracker.transmittance(origin, direction, 10.0f, random);
    sum += t;
    sum_squares += t * t;
    escaped += std::isinf(tracker.sampleCollision(origin, direction, 10.0f, random));
  }
  const double mean = sum / kSamples;
  const double se = std::sqrt((sum_squares / kSamples - mean * mean) / (kSamples - 1));
  // The mean transmittance, its standard error from the samples' spread (1e-6 for float
  // rounding); the escapes, each with the probability the transmittance gives.
  EXPECT_TRUE(kFamily.tTest(mean, expected, se, kSamples - 1, 1e-6)) << "optical depth " << depth;
  EXPECT_TRUE(kFamily.binomial(std::size_t(escaped), kSamples, expected))
      << "optical depth " << depth;
}

INSTANTIATE_TEST_SUITE_P(Offsets, Transmittance, ::testing::Values(0.0, 0.25, 0.6, 0.95));

class HenyeyGreensteinChiSquare : public ::testing::TestWithParam<float> {};

TEST_P(HenyeyGreensteinChiSquare, MatchesItsDensity) {
  const float g = GetParam();
  const glm::vec3 incoming = glm::normalize(glm::vec3(0.3f, -0.4f, 0.8f));
  EXPECT_TRUE(kFamily.chiSquare(
      [&](SampleStream& r) {
        return sampleHenyeyGreenstein(incoming, g, {r.next(), r.next()});
      },
      [&](const glm::vec3& w) { return double(henyeyGreenstein(glm::dot(incoming, w), g)); }))
      << "g = " << g;
}

INSTANTIATE_TEST_SUITE_P(Asymmetries, HenyeyGreensteinChiSquare,
                         ::testing::Values(-0.7f, 0.0f, 0.3f, 0.6f, 0.85f));

// A small cloud of overlapping particles with no surfaces, under a uniform sky.
scene::Scene makeCloudScene(float albedo, float g) {
  scene::Scene s;
  s.name = "test_cloud";
  for (int i = 0; i < 12; ++i) {
    const float a = 0.5f * float(i);
    s.medium.particles.push_back(
        {{0.6f * std::cos(a), 0.3f * std::sin(1.7f * a), 0.6f * std::sin(a)}, 0.7f, 6.0f});
  }
  s.medium.albedo = scene::Rgb(albedo);
  s.medium.g = g;
  s.sky_radiance = scene::Rgb(0.7f);
  s.camera.position = {0, 0.5f, -4};
  s.camera.look_at = {0, 0, 0};
  s.camera.vertical_fov_deg = 35;
  return s;
}

TEST(VolumetricFurnace, NonAbsorbingMediumUnderUniformSkyShowsTheSky) {
  // Albedo 1 under a uniform sky: whatever the paths do, the radiance is the sky's, 0.7.
  for (float g : {0.0f, 0.6f}) {
    const scene::Scene s = makeCloudScene(1.0f, g);
    for (glm::vec3 eye : {glm::vec3(0, 0.5f, -4), glm::vec3(3, -2, 1)}) {
      scene::Scene view = s;
      view.camera.position = eye;
      RenderSettings settings;
      settings.width = settings.height = kFurnaceSize;
      settings.spp = 64;
      const RenderResult r = renderReference(view, settings);
      // Each value's statistic follows Student's t with the render's degrees of freedom (1e-5
      // for float rounding).
      for (std::size_t i = 0; i < r.mean.data().size(); ++i)
        EXPECT_TRUE(kFamily.tTest(r.mean.data()[i], 0.7, std::sqrt(double(r.variance.data()[i])),
                                  double(r.variance_dof), 1e-5))
            << "value " << i << " g " << g << " eye " << eye.x;
      const test::ImageMean m = test::imageMean(r);
      EXPECT_TRUE(kFamily.tTest(m.mean, 0.7, m.standard_error, m.dof, 1e-6)) << "g " << g;
    }
  }
}

TEST(MediumPathClasses, SingleScatteringDiffersFromAllOrdersWhichConverges) {
  scene::Scene s = makeCloudScene(0.9f, 0.0f);
  s.sky_radiance = scene::Rgb(0.0f);
  s.directional_lights.push_back({glm::normalize(glm::vec3(-1, -1, 0.3f)), scene::Rgb(3.0f)});
  RenderSettings settings;
  settings.width = settings.height = 16;
  settings.spp = 256;
  settings.path_class.max_bounces = 1;
  const RenderResult single = renderReference(s, settings);
  settings.path_class.max_bounces = PathClass::kUnlimited;
  const RenderResult all = renderReference(s, settings);
  double single_sum = 0, all_sum = 0, variance_sum = 0;
  for (std::size_t i = 0; i < all.mean.data().size(); ++i) {
    single_sum += single.mean.data()[i];
    all_sum += all.mean.data()[i];
    variance_sum += single.variance.data()[i] + all.variance.data()[i];
  }
  // Multiple scattering adds light: far more than the noise of the two estimates.
  EXPECT_GT(all_sum - single_sum, 10 * std::sqrt(variance_sum));
  // The direct layer of the all-orders render is the single-scattering image, within the noise
  // of the two renders' variance layers (768 values: a normal statistic).
  double direct_sum = 0;
  for (float v : all.direct.data()) direct_sum += v;
  EXPECT_TRUE(kFamily.zTest(direct_sum, single_sum, std::sqrt(variance_sum)));

  // Convergence of all orders: RMSE against a 4096-spp render falls as spp^(−1/2).
  RenderSettings high = settings;
  high.width = high.height = 12;
  high.spp = 4096;
  high.seed = 1;
  const image::Image truth = renderReference(s, high).mean;
  RenderSettings low = high;
  low.spp = 64;
  low.seed = 2;
  std::vector<double> log_spp, log_error;
  renderReference(s, low, [&](std::uint32_t spp, const image::Image& mean) {
    double sum = 0;
    for (std::size_t i = 0; i < mean.data().size(); ++i) {
      const double d = double(mean.data()[i]) - truth.data()[i];
      sum += d * d;
    }
    log_spp.push_back(std::log(double(spp)));
    log_error.push_back(0.5 * std::log(sum / double(mean.data().size())));
  });
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < log_spp.size(); ++i) {
    mx += log_spp[i] / double(log_spp.size());
    my += log_error[i] / double(log_spp.size());
  }
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < log_spp.size(); ++i) {
    sxx += (log_spp[i] - mx) * (log_spp[i] - mx);
    sxy += (log_spp[i] - mx) * (log_error[i] - my);
  }
  EXPECT_NEAR(sxy / sxx, -0.5, 0.1);
}

}  // namespace
}  // namespace gib::ref
