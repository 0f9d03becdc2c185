// Chi-square goodness-of-fit tests of the direction samplers against their densities
// (pbrt-v4's approach): bin 10⁶ samples on the sphere, integrate the density over each bin
// numerically, pool bins with an expected count below 5, and reject at a family-wise
// significance of 1% (Šidák-corrected over the tests in this file).
#include "reference/sampling.h"
#include "metrics/distributions.h"
#include "reference/bsdf.h"
#include "reference/rng.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <functional>
#include <string>

namespace gib::ref {
namespace {

constexpr int kCosThetaBins = 64;
constexpr int kPhiBins = 32;
constexpr int kSamples = 1000000;
constexpr double kFamilySignificance = 0.01;
constexpr double kTestsInFile = 6;  // chi-square tests below, for the Šidák correction
constexpr double kMinExpected = 5;  // the usual validity condition of the chi-square statistic

using DirectionSampler = std::function<glm::vec3(SampleStream&)>;
using DirectionPdf = std::function<double(const glm::vec3&)>;

int binOf(const glm::vec3& w) {
  double cos_theta = std::clamp(double(w.z), -1.0, 1.0);
  int i = std::min(int((cos_theta + 1.0) * 0.5 * kCosThetaBins), kCosThetaBins - 1);
  double phi = std::atan2(double(w.y), double(w.x));
  if (phi < 0) phi += 2 * M_PI;
  int j = std::min(int(phi / (2 * M_PI) * kPhiBins), kPhiBins - 1);
  return i * kPhiBins + j;
}

// Expected probability of each bin: the density integrated over (cos θ, φ) with a midpoint rule
// (the area element on the sphere is d(cos θ) dφ). The cos θ steps are fine enough to resolve a
// Phong lobe of exponent 100, whose width in cos θ is about 1/101.
std::vector<double> expectedProbabilities(const DirectionPdf& pdf) {
  constexpr int kSubZ = 64;
  constexpr int kSubPhi = 12;
  std::vector<double> p(kCosThetaBins * kPhiBins, 0.0);
  const double dz = 2.0 / kCosThetaBins / kSubZ;
  const double dphi = 2 * M_PI / kPhiBins / kSubPhi;
  for (int i = 0; i < kCosThetaBins * kSubZ; ++i)
    for (int j = 0; j < kPhiBins * kSubPhi; ++j) {
      double z = -1.0 + (i + 0.5) * dz;
      double phi = (j + 0.5) * dphi;
      double r = std::sqrt(std::max(0.0, 1 - z * z));
      glm::vec3 w(r * std::cos(phi), r * std::sin(phi), z);
      p[(i / kSubZ) * kPhiBins + j / kSubPhi] += pdf(w) * dz * dphi;
    }
  return p;
}

// Returns the p-value of the chi-square statistic; fails the test if the density does not
// integrate to the fraction of samples that produced a direction.
double chiSquarePValue(const DirectionSampler& sample, const DirectionPdf& pdf) {
  std::vector<double> observed(kCosThetaBins * kPhiBins, 0.0);
  for (int s = 0; s < kSamples; ++s) {
    SampleStream random(99, 0, std::uint32_t(s));
    observed[binOf(sample(random))] += 1;
  }
  std::vector<double> expected = expectedProbabilities(pdf);
  double total = 0;
  for (double& e : expected) {
    total += e;
    e *= kSamples;
  }
  EXPECT_NEAR(total, 1.0, 1e-3) << "the density does not integrate to one";

  // Pool the sparse bins into one so every cell meets the validity condition.
  double chi2 = 0, pooled_observed = 0, pooled_expected = 0;
  int cells = 0;
  for (std::size_t b = 0; b < observed.size(); ++b) {
    if (expected[b] < kMinExpected) {
      pooled_observed += observed[b];
      pooled_expected += expected[b];
      continue;
    }
    chi2 += (observed[b] - expected[b]) * (observed[b] - expected[b]) / expected[b];
    ++cells;
  }
  if (pooled_expected > 0) {
    chi2 += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) /
            std::max(pooled_expected, 1e-9);
    ++cells;
  }
  return metrics::chiSquareSurvival(chi2, cells - 1);
}

double perTestSignificance() {
  return metrics::sidakSignificance(kFamilySignificance, kTestsInFile);
}

TEST(SamplingChiSquare, CosineHemisphereMatchesItsDensity) {
  double p = chiSquarePValue(
      [](SampleStream& r) {
        return sampleCosineHemisphere({r.next(), r.next()});
      },
      [](const glm::vec3& w) { return double(cosineHemispherePdf(w.z)); });
  EXPECT_GT(p, perTestSignificance());
}

class PhongLobeChiSquare : public ::testing::TestWithParam<float> {};

TEST_P(PhongLobeChiSquare, MatchesItsDensity) {
  const float n = GetParam();
  double p = chiSquarePValue(
      [n](SampleStream& r) {
        return samplePhongLobe({r.next(), r.next()}, n);
      },
      [n](const glm::vec3& w) { return double(phongLobePdf(w.z, n)); });
  EXPECT_GT(p, perTestSignificance()) << "exponent " << n;
}

INSTANTIATE_TEST_SUITE_P(Exponents, PhongLobeChiSquare, ::testing::Values(1.0f, 10.0f, 100.0f));

// The full material sampler: lobe selection plus both warps, for an oblique ωo, against
// Bsdf::pdf, in the local frame of the normal (+z).
TEST(SamplingChiSquare, PhongMaterialSamplerMatchesItsPdf) {
  scene::Material m;
  m.type = scene::MaterialType::kPhong;
  m.diffuse = scene::Rgb(0.3f);
  m.specular = scene::Rgb(0.5f);
  m.exponent = 20;
  const glm::vec3 wo = glm::normalize(glm::vec3(0.6f, 0.1f, 0.5f));
  const Bsdf bsdf(m, {0, 0, 1}, wo);
  // Glossy-lobe samples may fall below the surface, where Bsdf::pdf is zero because such a path
  // ends; the sampler's density there is the glossy share (0.5 / 0.8 by luminance) of the lobe.
  double p = chiSquarePValue(
      [&](SampleStream& r) {
        float u = r.next();
        return bsdf.sample(u, {r.next(), r.next()}).wi;
      },
      [&](const glm::vec3& w) {
        if (w.z > 0) return double(bsdf.pdf(w));
        // Below the surface only the glossy lobe reaches: its density there.
        glm::vec3 mirror = 2.0f * wo.z * glm::vec3(0, 0, 1) - wo;
        return (0.5 / 0.8) * double(phongLobePdf(glm::dot(mirror, w), m.exponent));
      });
  EXPECT_GT(p, perTestSignificance());
}

TEST(SamplingChiSquare, UniformHemisphereMatchesItsDensity) {
  double p = chiSquarePValue(
      [](SampleStream& r) {
        return sampleUniformHemisphere({r.next(), r.next()});
      },
      [](const glm::vec3& w) { return w.z > 0 ? double(kUniformHemispherePdf) : 0.0; });
  EXPECT_GT(p, perTestSignificance());
}

TEST(SamplingChiSquare, RejectsAWrongDensity) {
  // The test must be able to fail: cosine samples against a uniform-hemisphere density.
  double p = chiSquarePValue(
      [](SampleStream& r) {
        return sampleCosineHemisphere({r.next(), r.next()});
      },
      [](const glm::vec3& w) { return w.z > 0 ? double(kUniformHemispherePdf) : 0.0; });
  EXPECT_LT(p, 1e-6);
}

TEST(Frame, IsOrthonormalForAnyNormal) {
  for (std::uint32_t i = 0; i < 1000; ++i) {
    SampleStream r(5, i, 0);
    float z = 2 * r.next() - 1, phi = 2 * kPi * r.next();
    float s = std::sqrt(std::max(0.0f, 1 - z * z));
    glm::vec3 n(s * std::cos(phi), s * std::sin(phi), z);
    Frame f(n);
    EXPECT_NEAR(glm::dot(f.s, f.t), 0, 1e-5);
    EXPECT_NEAR(glm::dot(f.s, f.n), 0, 1e-5);
    EXPECT_NEAR(glm::dot(f.t, f.n), 0, 1e-5);
    EXPECT_NEAR(glm::length(f.s), 1, 1e-5);
    EXPECT_NEAR(glm::length(f.t), 1, 1e-5);
  }
}

}  // namespace
}  // namespace gib::ref
