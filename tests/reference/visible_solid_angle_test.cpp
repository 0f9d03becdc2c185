// The exact visible solid angle of a square light behind a square occluder (scene/
// polygon_solid_angle.h, Fournier & Péroche §6.1) against Embree shadow rays: uniform points on
// the light, each weighted by the solid angle its area element subtends when the segment to it is
// clear, estimate the same integral.
#include "reference/embree_scene.h"
#include "reference/rng.h"
#include "scene/mesh_builder.h"
#include "scene/occluded_light_bench.h"
#include "scene/polygon_solid_angle.h"
#include "support/statistical_test.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace gib::ref {
namespace {

constexpr std::uint32_t kSamples = 200000;
constexpr std::uint64_t kSeed = 20240611;
// A correct estimate misses the exact value at one of the five points (a t test each, 199 999
// degrees of freedom) with probability 1%.
constexpr test::TestFamily kFamily(0.01, 5);
// Shadow rays stop this fraction short of the light, so that they cannot hit it.
constexpr double kShortOfTheLight = 1e-6;

constexpr double kLightHeight = 2.0, kLightArea = 1.0;
const glm::dvec3 kLightNormal(0, -1, 0);

// The unit square light at y = 2 centred over the origin, and the occluder of side 0.6 at y = 1.
const scene::OccludedLightBench kBench = scene::occludedLightBench();
const std::vector<glm::dvec3>& kLight = kBench.light;
const std::vector<glm::dvec3>& kOccluder = kBench.occluder;

scene::Mesh quadMesh(const std::vector<glm::dvec3>& quad, std::uint32_t material) {
  scene::Mesh mesh;
  mesh.material = material;
  scene::appendQuad(mesh, glm::vec3(quad[0]), glm::vec3(quad[1]), glm::vec3(quad[2]),
                    glm::vec3(quad[3]));
  return mesh;
}

// The light (two triangles facing −y, emissive) and the occluder, nothing else.
scene::Scene lightBehindOccluder() {
  scene::Scene s;
  s.name = "light_behind_occluder";
  scene::Material emitter, blocker;
  emitter.name = "light";
  emitter.emission = scene::Rgb(1.0f);
  blocker.name = "occluder";
  blocker.diffuse = scene::Rgb(0.5f);
  s.materials = {emitter, blocker};
  s.meshes = {quadMesh(kLight, 0), quadMesh(kOccluder, 1)};
  s.meshes[0].name = "light";
  s.meshes[1].name = "occluder";
  return s;
}

struct Estimate {
  double mean = 0;
  double standard_error = 0;
};

// ∫ over the light of V(x, q) cos θ_q / |q − x|² dA(q), with q uniform on the light (pdf 1/A).
Estimate estimateVisibleSolidAngle(const EmbreeScene& embree, const glm::dvec3& x,
                                   std::uint32_t point) {
  double sum = 0, sum_of_squares = 0;
  for (std::uint32_t i = 0; i < kSamples; ++i) {
    SampleStream stream(kSeed, point, i);
    const double u = stream.next(), v = stream.next();
    const glm::dvec3 q(-0.5 + u, kLightHeight, -0.5 + v);
    const double distance = glm::length(q - x);
    const glm::dvec3 direction = (q - x) / distance;
    double weight = 0;
    if (!embree.occluded(glm::vec3(x), glm::vec3(direction), 0.0f,
                         float(distance * (1 - kShortOfTheLight)))) {
      const double cos_light = std::abs(glm::dot(kLightNormal, direction));
      weight = kLightArea * cos_light / (distance * distance);
    }
    sum += weight;
    sum_of_squares += weight * weight;
  }
  const double mean = sum / kSamples;
  const double variance = (sum_of_squares - kSamples * mean * mean) / (kSamples - 1);
  return {mean, std::sqrt(std::max(variance, 0.0) / kSamples)};
}

TEST(VisibleSolidAngle, MatchesEmbreeShadowRaysWherePartlyOccluded) {
  const EmbreeScene embree(lightBehindOccluder());
  // Points on y = 0 that see between 10% and 90% of the light (asserted below).
  const std::vector<glm::dvec3> points = {
      {0.2, 0, 0}, {0, 0, 0}, {1.0, 0, 0.8}, {-0.4, 0, 0.2}, {0.3, 0, 0.9}};
  for (std::uint32_t p = 0; p < points.size(); ++p) {
    const glm::dvec3& x = points[p];
    SCOPED_TRACE(testing::Message() << "x = (" << x.x << ", " << x.y << ", " << x.z << ")");
    const double exact = scene::visibleSolidAngle(x, kLight, kOccluder);
    const double visible_fraction = exact / scene::polygonSolidAngle(x, kLight);
    EXPECT_GT(visible_fraction, 0.1);
    EXPECT_LT(visible_fraction, 0.9);
    const Estimate estimate = estimateVisibleSolidAngle(embree, x, p);
    EXPECT_GT(estimate.standard_error, 0.0);
    EXPECT_TRUE(kFamily.tTest(estimate.mean, exact, estimate.standard_error, kSamples - 1));
  }
}

}  // namespace
}  // namespace gib::ref
