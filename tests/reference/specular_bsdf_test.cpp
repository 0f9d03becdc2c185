// Mirror and glass as the reference samples them (reference/bsdf.h): the glass's choice between
// its reflection and refraction lobes against their probabilities F and 1 − F (a chi-square test
// per angle), the directions against the laws of reflection and refraction, the weights of a
// lossless interface, the conductor's weight against its Fresnel function, and the shading-normal
// rule. A correct implementation fails this file's statistical tests with probability 1%.
#include "reference/bsdf.h"
#include "reference/rng.h"
#include "scene/fresnel_shared.h"
#include "support/statistical_test.h"
#include "support/test_materials.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <vector>

namespace gib::ref {
namespace {

constexpr int kAngles = 6;
constexpr int kSides = 2;
constexpr test::TestFamily kFamily(0.01, kAngles* kSides);
constexpr int kSamples = 100000;

// wo at angle θ (cos θ = `cos_o`) from the normal +z, in the xz plane.
glm::vec3 direction(float cos_o) {
  return {std::sqrt(std::max(0.0f, 1.0f - cos_o * cos_o)), 0.0f, cos_o};
}

TEST(GlassBsdf, ChoosesReflectionAndRefractionWithTheirFresnelProbabilities) {
  const scene::Material m = test::glassMaterial(1.5f);
  const glm::vec3 n(0, 0, 1);
  SampleStream random(7, 0, 0);
  for (bool outside : {true, false}) {
    // From inside, cos 0.5 and below lie beyond the critical angle (cos θc = 0.745): all reflect.
    for (float cos_o : {1.0f, 0.9f, 0.75f, 0.5f, 0.2f, 0.05f}) {
      const Bsdf bsdf(m, n, n, direction(cos_o), outside);
      const float eta = outside ? 1.5f : 1.0f / 1.5f;
      const double reflectance = scene::fresnelDielectric(cos_o, eta);
      std::vector<double> observed(2, 0.0);
      for (int i = 0; i < kSamples; ++i) {
        const BsdfSample s = bsdf.sample({random.next(), random.next()}, Transport::kImportance);
        ASSERT_TRUE(s.specular);
        observed[s.refracted ? 1 : 0] += 1;
      }
      const std::vector<double> expected = {kSamples * reflectance, kSamples * (1 - reflectance)};
      if (reflectance >= 1.0) {
        EXPECT_EQ(observed[1], 0) << "refraction beyond the critical angle, cos " << cos_o;
        continue;
      }
      EXPECT_TRUE(kFamily.chiSquare(observed, expected))
          << (outside ? "outside" : "inside") << ", cos " << cos_o;
    }
  }
}

TEST(GlassBsdf, DirectionsFollowReflectionAndSnellsLaw) {
  const glm::vec3 n(0, 0, 1);
  const scene::Material m =
      test::glassMaterial(1.5f);  // a Bsdf refers to its material: it must outlive it
  for (bool outside : {true, false}) {
    const float eta = outside ? 1.5f : 1.0f / 1.5f;
    const Bsdf bsdf(m, n, n, direction(0.8f), outside);
    const glm::vec3 wo = direction(0.8f);
    for (float u : {0.0f, 0.99f}) {
      const BsdfSample s = bsdf.sample({u, 0.5f});
      EXPECT_NEAR(glm::length(s.wi), 1.0f, 1e-6f);
      EXPECT_NEAR(s.wi.y, 0.0f, 1e-6f);  // in the plane of incidence
      if (!s.refracted) {
        EXPECT_NEAR(s.wi.x, -wo.x, 1e-6f);
        EXPECT_NEAR(s.wi.z, wo.z, 1e-6f);
        EXPECT_FLOAT_EQ(s.weight.x, 1.0f);
      } else {
        // sin θi = η sin θt, on the other side, and radiance scaled by 1/η².
        EXPECT_NEAR(std::abs(wo.x), eta * std::abs(s.wi.x), 1e-6f);
        EXPECT_LT(s.wi.z, 0.0f);
        EXPECT_NEAR(s.weight.x, 1.0f / (eta * eta), 1e-6f);
        const BsdfSample flux = bsdf.sample({u, 0.5f}, Transport::kImportance);
        EXPECT_NEAR(flux.weight.x, 1.0f, 1e-6f) << "flux is not scaled by refraction";
      }
    }
  }
}

TEST(MirrorBsdf, ReflectsItsFresnelFractionIntoTheMirrorDirection) {
  scene::Material m;
  m.type = scene::MaterialType::kMirror;
  m.conductor_n = {0.18f, 0.42f, 1.37f};
  m.conductor_k = {3.42f, 2.35f, 1.77f};
  const glm::vec3 n(0, 0, 1);
  for (float cos_o : {1.0f, 0.5f, 0.1f}) {
    const Bsdf bsdf(m, n, n, direction(cos_o), true);
    const BsdfSample s = bsdf.sample({0.3f, 0.6f});
    const glm::vec3 expected = scene::fresnelConductor(cos_o, m.conductor_n, m.conductor_k);
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(s.weight[c], expected[c]);
    EXPECT_NEAR(s.wi.z, cos_o, 1e-6f);
    EXPECT_EQ(bsdf.evaluate(s.wi), Rgb(0.0f)) << "a delta lobe has no value for a given pair";
    EXPECT_EQ(bsdf.pdf(s.wi), 0.0f);
  }
  m.perfect_mirror = true;
  const Bsdf perfect(m, n, n, direction(0.3f), true);
  EXPECT_EQ(perfect.sample({0.5f, 0.5f}).weight, Rgb(1.0f));
}

// A shading normal that would send the reflected path into the surface gives way to the
// geometric normal, and the interface stays lossless.
TEST(SpecularBsdf, ShadingNormalThatSendsThePathInsideGivesWayToTheGeometricOne) {
  scene::Material m;
  m.type = scene::MaterialType::kMirror;
  m.perfect_mirror = true;
  const glm::vec3 ng(0, 0, 1);
  const glm::vec3 ns = glm::normalize(glm::vec3(0.6f, 0, 0.8f));
  const glm::vec3 wo = glm::normalize(glm::vec3(-1.0f, 0, 0.1f));  // grazing, against the tilt
  const BsdfSample s = Bsdf(m, ng, ns, wo, true).sample({0.5f, 0.5f});
  EXPECT_GT(glm::dot(s.wi, ng), 0.0f);
  EXPECT_NEAR(s.wi.x, -wo.x, 1e-6f);  // reflected about ng
  EXPECT_EQ(s.weight, Rgb(1.0f));
}

// Veach's adjoint correction: importance through a smooth (shading-normal) diffuse surface is
// weighted |ns·wo||ng·wi|/(|ng·wo||ns·wi|) relative to radiance, and is radiance's where ns = ng.
TEST(DiffuseBsdf, ImportanceCarriesTheShadingNormalCorrection) {
  scene::Material m;
  m.diffuse = Rgb(0.5f);
  const glm::vec3 ng(0, 0, 1);
  const glm::vec3 ns = glm::normalize(glm::vec3(0.2f, 0, 1.0f));
  const glm::vec3 wo = glm::normalize(glm::vec3(0.3f, 0.1f, 0.9f));
  const glm::vec3 wi = glm::normalize(glm::vec3(-0.5f, 0.2f, 0.6f));
  const Bsdf smooth(m, ng, ns, wo, true);
  const float correction = std::abs(glm::dot(ns, wo)) * std::abs(glm::dot(ng, wi)) /
                           (std::abs(glm::dot(ng, wo)) * std::abs(glm::dot(ns, wi)));
  EXPECT_NEAR(smooth.evaluateProjected(wi, Transport::kImportance).x,
              smooth.evaluateProjected(wi, Transport::kRadiance).x * correction, 1e-6f);
  const Bsdf flat(m, ng, ng, wo, true);
  EXPECT_FLOAT_EQ(flat.evaluateProjected(wi, Transport::kImportance).x,
                  flat.evaluateProjected(wi, Transport::kRadiance).x);
}

}  // namespace
}  // namespace gib::ref
