// Chi-square goodness-of-fit tests of the direction samplers against their densities
// (support/statistical_test.h).
#include "reference/sampling.h"
#include "reference/bsdf.h"
#include "reference/rng.h"
#include "support/statistical_test.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <functional>
#include <string>

namespace gib::ref {
namespace {

// A correct sampler fails one of this file's six chi-square tests (cosine, three Phong lobes, the
// Phong material, uniform) with probability 1%.
constexpr test::TestFamily kFamily(0.01, 6);

TEST(SamplingChiSquare, CosineHemisphereMatchesItsDensity) {
  EXPECT_TRUE(kFamily.chiSquare(
      [](SampleStream& r) {
        return sampleCosineHemisphere({r.next(), r.next()});
      },
      [](const glm::vec3& w) { return double(cosineHemispherePdf(w.z)); }));
}

class PhongLobeChiSquare : public ::testing::TestWithParam<float> {};

TEST_P(PhongLobeChiSquare, MatchesItsDensity) {
  const float n = GetParam();
  EXPECT_TRUE(kFamily.chiSquare(
      [n](SampleStream& r) {
        return samplePhongLobe({r.next(), r.next()}, n);
      },
      [n](const glm::vec3& w) { return double(phongLobePdf(w.z, n)); }))
      << "exponent " << n;
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
  const glm::vec3 n(0, 0, 1);
  const Bsdf bsdf(m, n, n, wo, /*outside=*/true);
  // Glossy-lobe samples may fall below the surface, where Bsdf::pdf is zero because such a path
  // ends; the sampler's density there is the glossy share (0.5 / 0.8 by luminance) of the lobe.
  EXPECT_TRUE(kFamily.chiSquare(
      [&](SampleStream& r) {
        return bsdf.sample({r.next(), r.next()}).wi;
      },
      [&](const glm::vec3& w) {
        if (w.z > 0) return double(bsdf.pdf(w));
        // Below the surface only the glossy lobe reaches: its density there.
        glm::vec3 mirror = 2.0f * wo.z * glm::vec3(0, 0, 1) - wo;
        return (0.5 / 0.8) * double(phongLobePdf(glm::dot(mirror, w), m.exponent));
      }));
}

TEST(SamplingChiSquare, UniformHemisphereMatchesItsDensity) {
  EXPECT_TRUE(kFamily.chiSquare(
      [](SampleStream& r) {
        return sampleUniformHemisphere({r.next(), r.next()});
      },
      [](const glm::vec3& w) { return w.z > 0 ? double(kUniformHemispherePdf) : 0.0; }));
}

TEST(SamplingChiSquare, RejectsAWrongDensity) {
  // The test must be able to fail: cosine samples against a uniform-hemisphere density.
  EXPECT_FALSE(kFamily.chiSquare(
      [](SampleStream& r) {
        return sampleCosineHemisphere({r.next(), r.next()});
      },
      [](const glm::vec3& w) { return w.z > 0 ? double(kUniformHemispherePdf) : 0.0; }));
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
