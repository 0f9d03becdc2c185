// Hardware sampling of an area light's visible solid angle (Fournier & Péroche §4, §6.1), checked
// against the exact value of scene/polygon_solid_angle.h on the paper's bench geometry.
#include "realtime/techniques/jittered_light_sampling/solid_angle_bench.h"

#include "common/input_error.h"
#include "metrics/timing_statistics.h"
#include "scene/polygon_solid_angle.h"
#include "support/gl_test_context.h"
#include "support/render_statistics.h"
#include "support/statistical_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace gib {
namespace {

using rt::CoverageScheme;
using rt::CoverageSettings;

CoverageSettings settingsFor(const char* scheme, int size, std::uint32_t seed = 1) {
  CoverageSettings s;
  rt::parseCoverageScheme(scheme, s);
  s.size = size;
  s.seed = seed;
  return s;
}

class JitteredLightSampling : public test::GlTest {
 protected:
  scene::OccludedLightBench bench_ = scene::occludedLightBench();
  double exact(const glm::dvec3& x) const {
    return scene::visibleSolidAngle(x, bench_.light, bench_.occluder);
  }
  double estimate(const CoverageSettings& s, const glm::dvec3& x, std::uint32_t point = 0) {
    rt::LightCoverageSampler sampler(rt::quadTriangles(bench_.light),
                                     rt::quadTriangles(bench_.occluder), s);
    return sampler.visibleSolidAngle(x, point, nullptr);
  }
};

// Points on the receiving plane where the occluder hides part of the light, and one where it
// hides none of it.
const std::vector<glm::dvec3> kPartlyHidden = {{0.9, 0, 0.0},   {1.0, 0, -0.4}, {0.1, 0, 0.5},
                                               {0.45, 0, -0.2}, {0.9, 0, 0.6},  {0.5, 0, 1.0}};
const glm::dvec3 kUnoccluded(-1.8, 0, -1.7);

// Unbiased jittered sampling misses one of this file's statistical tests (its mean error at each
// partly hidden point) with probability 1%.
const test::TestFamily kFamily(0.01, int(kPartlyHidden.size()));

TEST_F(JitteredLightSampling, TheTestPointsSeeThePartialOcclusionTheyAreChosenFor) {
  for (const glm::dvec3& x : kPartlyHidden) {
    const double light = scene::polygonSolidAngle(x, bench_.light);
    EXPECT_GT(exact(x), 0.1 * light) << x.x << "," << x.z;
    EXPECT_LT(exact(x), 0.9 * light) << x.x << "," << x.z;
  }
  EXPECT_DOUBLE_EQ(exact(kUnoccluded), scene::polygonSolidAngle(kUnoccluded, bench_.light));
}

// Seen from a point far off axis the light's pixels subtend very different solid angles: the
// regular and jittered schemes weigh each sample by its own (eq. 3). The occlusion query weighs
// every pixel alike, which is exact only while every pixel is visible: the window is the light.
TEST_F(JitteredLightSampling, AnUnoccludedLightIsMeasuredByEverySchemeWithItsPixelWeights) {
  const double truth = exact(kUnoccluded);
  EXPECT_NEAR(estimate(settingsFor("regular", 32), kUnoccluded), truth, 1e-3 * truth);
  EXPECT_NEAR(estimate(settingsFor("jittered1", 32), kUnoccluded), truth, 1e-3 * truth);
  EXPECT_NEAR(estimate(settingsFor("jittered8", 32), kUnoccluded), truth, 1e-3 * truth);
  EXPECT_NEAR(estimate(settingsFor("occlusion_query", 32), kUnoccluded), truth, 1e-3 * truth);
}

// Unbiased: over 64 seeds the mean error at each point is zero within its standard error: each
// point's (mean − 0)/standard error follows Student's t with 63 degrees of freedom.
// Regular sampling is deterministic: its error on the grid-aligned occluder edges does not
// average out, and over the points it stands far beyond the standard error the jittered means
// reach (the root mean squares of both, five times apart; about thirteen when this was written).
TEST_F(JitteredLightSampling, JitteredSamplingIsUnbiasedAndRegularSamplingIsNot) {
  constexpr int kSeeds = 64;
  double regular_squares = 0, se_squares = 0;
  for (const glm::dvec3& x : kPartlyHidden) {
    const double truth = exact(x);
    std::vector<double> errors;
    for (int seed = 0; seed < kSeeds; ++seed)
      errors.push_back(estimate(settingsFor("jittered1", 32, std::uint32_t(seed)), x) - truth);
    const test::MeanEstimate error = test::sampleMean(errors);
    const double mean = error.mean, se = error.standard_error;
    ASSERT_GT(se, 0) << "jittered samples must differ between seeds";
    EXPECT_TRUE(kFamily.tTest(mean, 0.0, se, error.dof)) << "point " << x.x << "," << x.z;
    const double regular_error = estimate(settingsFor("regular", 32), x) - truth;
    regular_squares += regular_error * regular_error;
    se_squares += se * se;
  }
  EXPECT_GT(std::sqrt(regular_squares), 5 * std::sqrt(se_squares))
      << "regular sampling's error should stand out as a bias";
}

// The ordering of the paper's Fig. 7 on a 20 × 20 grid of the plane at 32²: jittering reduces the
// mean error, and four samples per pixel reduce it further.
TEST_F(JitteredLightSampling, JitteringAndMoreSamplesPerPixelReduceTheMeanError) {
  const scene::OccludedLightBench small = scene::occludedLightBench(20);
  auto meanError = [&](const char* scheme) {
    return rt::measureScheme(small, settingsFor(scheme, 32), 0).mean_abs_error;
  };
  const double regular = meanError("regular");
  const double jittered1 = meanError("jittered1");
  const double jittered4 = meanError("jittered4");
  EXPECT_LT(jittered1, regular);
  EXPECT_LT(jittered4, jittered1);
}

// The bench's outputs recomputed: at each grid point its error is what a sampler of its own
// estimates there with the same jitter (on the first pass over the points a point's index in
// occludedLightBenchPoints' order names it in the hash), less the exact visible solid angle; and
// the mean absolute error is theirs. The same rasterized samples weighed by the same double
// arithmetic give the same bits, so EXPECT_DOUBLE_EQ's 4 ULPs leave room for nothing else: an
// error of the wrong point, jitter or sign is off by about the scheme's own error (1e-6 to 2e-4 sr
// at these points), far beyond them. The timed samples cover the requested count, later passes
// over the points included, every phase timed.
TEST_F(JitteredLightSampling,
       ErrorsAreEachPointsEstimateLessItsExactValueAndTimingsCoverTheSamples) {
  const scene::OccludedLightBench small = scene::occludedLightBench(4);
  const CoverageSettings settings = settingsFor("jittered4", 16);
  const rt::SchemeMeasurement m = rt::measureScheme(small, settings, 40);
  const std::vector<glm::dvec3> points = scene::occludedLightBenchPoints(small);
  ASSERT_EQ(m.errors.size(), points.size());
  rt::LightCoverageSampler sampler(rt::quadTriangles(small.light),
                                   rt::quadTriangles(small.occluder), settings);
  double mean_abs_error = 0;
  for (std::size_t p = 0; p < points.size(); ++p) {
    const double error = sampler.visibleSolidAngle(points[p], std::uint32_t(p), nullptr) -
                         scene::visibleSolidAngle(points[p], small.light, small.occluder);
    EXPECT_DOUBLE_EQ(m.errors[p], error) << "point " << p;
    mean_abs_error += std::abs(error) / double(points.size());
  }
  EXPECT_DOUBLE_EQ(m.mean_abs_error, mean_abs_error);

  EXPECT_EQ(m.phase_times.size(), 40u);
  for (double rt::CoveragePhaseTimes::*phase :
       {&rt::CoveragePhaseTimes::render_ms, &rt::CoveragePhaseTimes::read_back_ms,
        &rt::CoveragePhaseTimes::weight_ms}) {
    std::vector<double> samples;
    for (const rt::CoveragePhaseTimes& t : m.phase_times) samples.push_back(t.*phase);
    EXPECT_GT(metrics::summarizeTimings(samples).median, 0);
  }
}

TEST(JitteredLightSamplingInput, UnknownSchemesAndSizesOutOfRangeAreInputErrors) {
  CoverageSettings s;
  EXPECT_THROW(rt::parseCoverageScheme("jittered2", s), InputError);
  EXPECT_THROW(rt::parseCoverageScheme("random", s), InputError);
  EXPECT_THROW(rt::validateCoverageSize(2), InputError);
  EXPECT_THROW(rt::validateCoverageSize(1024), InputError);
  EXPECT_NO_THROW(rt::validateCoverageSize(48));
  for (const std::string& name : rt::coverageSchemeNames()) {
    rt::parseCoverageScheme(name, s);
    EXPECT_EQ(rt::coverageSchemeName(s), name);
  }
}

}  // namespace
}  // namespace gib
