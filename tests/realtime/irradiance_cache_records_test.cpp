// The irradiance cache's records on the CPU (course notes 001; Ward 1988, Ward & Heckbert 1992):
// the weighting function against Ward's formula and its simplified form, the zone's screen
// rectangle, the octree against a brute-force sum, the placement's cover, and Ward & Heckbert's
// stratified estimates (irradiance, rotation and translation gradients) against closed forms.
#include "realtime/irradiance_cache/record_octree.h"
#include "realtime/irradiance_cache/record_placement.h"
#include "realtime/techniques/irradiance_cache/ward_hemisphere.h"
#include "scene/camera.h"
#include "support/form_factor.h"
#include "support/render_statistics.h"
#include "support/statistical_test.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <random>

namespace gib::rt {
namespace {

constexpr double kPi = std::numbers::pi;

// A correct Ward hemisphere misses this file's one statistical test (a patch's irradiance against
// its form factor) with probability 1%.
constexpr test::TestFamily kFamily(0.01, 1);

gpu::IrradianceRecord makeRecord(const glm::vec3& p, const glm::vec3& n, float radius,
                                 const glm::vec3& e = glm::vec3(1.0f)) {
  gpu::IrradianceRecord r{};
  r.position_radius = glm::vec4(p, radius);
  r.normal = glm::vec4(glm::normalize(n), 0.0f);
  r.irradiance = glm::vec4(e, 0.0f);
  return r;
}

glm::vec3 randomUnit(std::mt19937& rng) {
  std::normal_distribution<float> g;
  return glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
}

TEST(IrradianceCacheWeight, IsWardsFormula) {
  const gpu::IrradianceRecord r = makeRecord({1, 2, 3}, {0, 1, 0}, 0.5f);
  // |P − P_k| = 0.3, n·n_k = cos 60° = 0.5: w = 1 / (0.3/0.5 + √0.5).
  const glm::vec3 p(1.3f, 2.0f, 3.0f), n(std::sqrt(0.75f), 0.5f, 0.0f);
  EXPECT_NEAR(gpu::recordWeight(r, p, n), 1.0 / (0.6 + std::sqrt(0.5)), 1e-5);
  // At the record itself the weight is as large as the floor of its denominator allows.
  EXPECT_GT(gpu::recordWeight(r, {1, 2, 3}, {0, 1, 0}), 1e5f);
}

// The simplified weight R/|P − P_k| bounds the full one, so the sphere of radius a·R holds every
// point the record contributes to: 100 000 random points, none with w > 1/a outside it.
TEST(IrradianceCacheWeight, TheSimplifiedWeightBoundsTheZone) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const float a = 0.3f;
  int inside = 0;
  for (int i = 0; i < 100000; ++i) {
    const gpu::IrradianceRecord r = makeRecord({0, 0, 0}, randomUnit(rng), 0.8f);
    const glm::vec3 p(u(rng), u(rng), u(rng));
    const glm::vec3 n = glm::normalize(glm::vec3(r.normal) + 0.3f * randomUnit(rng));
    const float w = gpu::recordWeight(r, p, n);
    if (w <= 1.0f / a) continue;
    ++inside;
    EXPECT_LE(glm::length(p), a * 0.8f * (1 + 1e-6f));
    EXPECT_LE(w, 0.8f / glm::length(p) * (1 + 1e-6f));
  }
  EXPECT_GT(inside, 50);
}

// A record's extrapolation: E_k at P_k, and first-order changes along the gradients.
TEST(IrradianceCacheWeight, ExtrapolationAppliesBothGradients) {
  gpu::IrradianceRecord r = makeRecord({0, 0, 0}, {0, 0, 1}, 1.0f, {2, 2, 2});
  r.translation[0] = glm::vec4(1, 0, 0, 0);
  r.rotation[1] = glm::vec4(0, 1, 0, 0);
  const glm::vec3 n = glm::normalize(glm::vec3(0.1f, 0, 1));
  const glm::vec3 e = gpu::recordIrradiance(r, {0.25f, 0, 0}, n);
  EXPECT_NEAR(e.r, 2.25f, 1e-6);                                       // +0.25 along x
  EXPECT_NEAR(e.g, 2.0f + glm::cross(glm::vec3(0, 0, 1), n).y, 1e-6);  // (n_k × n)·∇r
  EXPECT_NEAR(e.b, 2.0f, 1e-6);
  r.translation[2] = glm::vec4(-100, 0, 0, 0);
  EXPECT_EQ(gpu::recordIrradiance(r, {0.25f, 0, 0}, {0, 0, 1}).b, 0.0f);  // never negative
}

// What a camera sees: a 64 × 48 image of the plane y = 0 from above at an angle.
struct PlaneView {
  CameraTransform camera;
  SurfaceImage surfaces;
};
PlaneView planeView() {
  scene::Camera c;
  c.position = {0.0f, 2.0f, 3.0f};
  c.look_at = {0.0f, 0.0f, 0.0f};
  c.vertical_fov_deg = 50.0f;
  const int width = 64, height = 48;
  PlaneView v;
  v.camera = cameraTransform(c, width, height, {-5, -1, -5}, {5, 1, 5});
  const scene::CameraFrame frame = scene::makeCameraFrame(c, width, height);
  v.surfaces.width = width;
  v.surfaces.height = height;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::vec3 d = scene::cameraRayDirection(frame, width, height, float(x) + 0.5f,
                                                    float(height - y) - 0.5f);
      const float t = d.y < 0 ? -frame.origin.y / d.y : -1.0f;
      v.surfaces.valid.push_back(t > 0 ? 1 : 0);
      v.surfaces.position.push_back(frame.origin + std::max(t, 0.0f) * d);
      v.surfaces.normal.emplace_back(0.0f, 1.0f, 0.0f);
    }
  return v;
}

// Every pixel whose surface a record contributes to lies in the record's pixel rectangle (what
// the splat draws), for records of any size on the plane, also ones reaching behind the eye.
TEST(IrradianceCacheZone, TheRectangleHoldsEveryPixelTheRecordReaches) {
  const PlaneView v = planeView();
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.5f, 1.5f), radius(0.05f, 3.0f);
  const float a = 0.25f;
  int reached = 0;
  for (int i = 0; i < 200; ++i) {
    const gpu::IrradianceRecord r = makeRecord({u(rng), 0, u(rng)}, {0, 1, 0}, radius(rng));
    const glm::ivec4 rect = zonePixelRect(v.camera, 64, 48, r, a);
    for (int y = 0; y < 48; ++y)
      for (int x = 0; x < 64; ++x) {
        const std::size_t k = v.surfaces.index(x, y);
        if (!v.surfaces.valid[k]) continue;
        if (gpu::recordWeight(r, v.surfaces.position[k], v.surfaces.normal[k]) <= 1.0f / a)
          continue;
        ++reached;
        EXPECT_TRUE(x >= rect.x && x <= rect.z && y >= rect.y && y <= rect.w)
            << "record " << i << " pixel " << x << "," << y;
      }
  }
  EXPECT_GT(reached, 1000);
}

// The octree's lookup is the sum over every record, whatever the records' sizes.
TEST(IrradianceCacheOctree, LookupEqualsTheSumOverAllRecords) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-2.0f, 2.0f), radius(0.01f, 2.0f), e(0.0f, 5.0f);
  const float a = 0.2f;
  RecordOctree octree({-2, -2, -2}, {2, 2, 2}, a);
  std::vector<gpu::IrradianceRecord> records;
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 normal = glm::normalize(glm::vec3(0, 1, 0) + 0.3f * randomUnit(rng));
    gpu::IrradianceRecord r =
        makeRecord({u(rng), u(rng), u(rng)}, normal, radius(rng), {e(rng), e(rng), e(rng)});
    r.translation[0] = glm::vec4(randomUnit(rng), 0.0f);
    records.push_back(r);
    octree.insert(r);
  }
  EXPECT_GT(octree.nodeCount(), 10u);
  int covered = 0;
  for (int i = 0; i < 5000; ++i) {
    const glm::vec3 p(u(rng), u(rng), u(rng));
    const glm::vec3 n = glm::normalize(glm::vec3(0, 1, 0) + 0.3f * randomUnit(rng));
    glm::dvec4 expected(0.0);
    for (const gpu::IrradianceRecord& r : records) {
      const float w = gpu::recordWeight(r, p, n);
      if (w > 1.0f / a) expected += glm::dvec4(glm::dvec3(w * gpu::recordIrradiance(r, p, n)), w);
    }
    const glm::vec4 got = octree.lookup(p, n);
    if (expected.w > 0) ++covered;
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], expected[c], 1e-4 * (1 + expected[c]));
  }
  EXPECT_GT(covered, 500);
}

// The traversal leaves no pixel uncovered, covers each record's own pixel, and ends, in rounds
// and in the notes' scan order (one record a round, in increasing pixel order).
class IrradianceCachePlacement : public ::testing::TestWithParam<bool> {};

TEST_P(IrradianceCachePlacement, EveryPixelEndsCovered) {
  const PlaneView v = planeView();
  RecordPlacementSettings settings;
  settings.accuracy = 0.2f;
  settings.scanline = GetParam();
  RecordPlacement placement(v.surfaces, v.camera, settings);
  std::size_t previous_pixel = 0;
  int records = 0;
  for (;;) {
    const std::vector<glm::ivec2> round = placement.nextRound();
    if (round.empty()) break;
    std::vector<gpu::IrradianceRecord> fresh;
    if (settings.scanline) {
      ASSERT_EQ(round.size(), 1u);
      const std::size_t k = v.surfaces.index(round[0].x, round[0].y);
      EXPECT_GE(k, previous_pixel);
      previous_pixel = k;
    }
    for (const glm::ivec2& pixel : round) {
      const std::size_t k = v.surfaces.index(pixel.x, pixel.y);
      ASSERT_TRUE(v.surfaces.valid[k]);
      ASSERT_EQ(placement.weights()[k], 0.0f) << "a covered pixel got a record";
      fresh.push_back(makeRecord(v.surfaces.position[k], {0, 1, 0}, 2.0f));
    }
    placement.add(fresh);
    for (const glm::ivec2& pixel : round)
      EXPECT_GT(placement.weights()[v.surfaces.index(pixel.x, pixel.y)], 1.0f / settings.accuracy);
    records += int(round.size());
    ASSERT_LT(placement.rounds(), settings.scanline ? 64 * 48 : 100);
  }
  for (std::size_t k = 0; k < v.surfaces.valid.size(); ++k) {
    if (!v.surfaces.valid[k]) continue;
    EXPECT_GT(placement.weights()[k], 0.0f) << "pixel " << k;
  }
  EXPECT_GT(records, 4);
  EXPECT_LT(records, 64 * 48 / 4);  // far fewer records than pixels
}
INSTANTIATE_TEST_SUITE_P(Traversals, IrradianceCachePlacement, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "Scanline" : "Rounds"; });

// Ward & Heckbert's sampling of a radiance field given as a function of direction (and the
// distance to what is seen), at the origin with normal +z.
template <typename Field>
gpu::IrradianceRecord sampleField(const WardStrata& strata, std::uint32_t seed, Field field) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const glm::vec3 n(0, 0, 1), t = gpu::basisTangent(n), b = gpu::basisBitangent(n);
  std::vector<HemisphereSample> samples;
  for (int j = 0; j < strata.theta; ++j)
    for (int k = 0; k < strata.phi; ++k)
      samples.push_back(field(wardDirection(t, b, n, j, k, strata, {u(rng), u(rng)})));
  return wardRecord({0, 0, 0}, n, strata, samples);
}

// A float rounding, 2⁻²⁴ of the value rounded.
constexpr double kUnitRoundoff = 0x1p-24;

// A uniform sky: E = π·L exactly, R infinite, both gradients zero. E is the float π/(MN) times a
// float sum of MN equal radiances, exact for these (small multiples of powers of two), so E errs
// only by π's rounding and the division's and the product's: within 3 roundings.
TEST(WardHemisphere, AUniformSkyGivesPiTimesItsRadiance) {
  const gpu::IrradianceRecord r = sampleField(wardStrata(512), 1, [](const glm::vec3&) {
    return HemisphereSample{glm::vec3(1.0f, 0.5f, 2.0f)};
  });
  EXPECT_NEAR(r.irradiance.x, kPi, 3 * kUnitRoundoff * kPi);
  EXPECT_NEAR(r.irradiance.z, 2 * kPi, 3 * kUnitRoundoff * 2 * kPi);
  EXPECT_TRUE(std::isinf(r.position_radius.w));
  for (int c = 0; c < 3; ++c) {
    EXPECT_LT(glm::length(glm::vec3(r.rotation[c])), 1e-4);
    EXPECT_LT(glm::length(glm::vec3(r.translation[c])), 1e-4);
  }
}

// A unit square of radiance 1 at height 1 over the point: E = π · the form factor (Lambert's
// formula). The jittered estimate's standard error comes from 16 independent seeds' spread, so
// (mean − E) / standard error follows Student's t with 15 degrees of freedom.
TEST(WardHemisphere, APatchsIrradianceIsPiTimesItsFormFactorWithinItsStandardError) {
  const std::vector<glm::dvec3> patch = {
      {-0.3, -0.5, 1}, {0.7, -0.5, 1}, {0.7, 0.5, 1}, {-0.3, 0.5, 1}};
  const double expected = kPi * test::pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, patch);
  auto field = [](const glm::vec3& w) {
    const glm::vec3 hit = w / w.z;
    const bool inside = hit.x > -0.3f && hit.x < 0.7f && hit.y > -0.5f && hit.y < 0.5f;
    return HemisphereSample{glm::vec3(inside ? 1.0f : 0.0f), 1.0f / w.z};
  };
  constexpr int kRuns = 16;
  std::vector<double> estimates;
  for (int s = 0; s < kRuns; ++s)
    estimates.push_back(sampleField(wardStrata(256), 100 + s, field).irradiance.x);
  const test::MeanEstimate e = test::sampleMean(estimates);
  ASSERT_GT(e.standard_error, 0.0) << "jittered seeds must differ";
  EXPECT_TRUE(kFamily.tTest(e.mean, expected, e.standard_error, e.dof));
}

// L(ω) = 1 + g·ω: E(n) = π + (2π/3) g·n, so rotating the normal by a small angle changes E as
// (n_k × n)·∇r E predicts, to first order (the residual is second order, plus sampling noise).
TEST(WardHemisphere, TheRotationGradientPredictsATiltedNormal) {
  const glm::vec3 g(0.6f, -0.3f, 0.2f);
  const gpu::IrradianceRecord r = sampleField(wardStrata(4096), 5, [&](const glm::vec3& w) {
    return HemisphereSample{glm::vec3(1.0f + glm::dot(g, w))};
  });
  for (const glm::vec3& tilt : {glm::vec3(0.05f, 0, 0), glm::vec3(0, 0.05f, 0)}) {
    const glm::vec3 n = glm::normalize(glm::vec3(0, 0, 1) + tilt);
    const double exact = kPi + 2 * kPi / 3 * glm::dot(g, n);
    const double change = exact - (kPi + 2 * kPi / 3 * g.z);
    const double predicted = glm::dot(glm::cross(glm::vec3(0, 0, 1), n), glm::vec3(r.rotation[0]));
    EXPECT_NEAR(predicted, change, 0.05 * std::abs(change)) << "tilt " << tilt.x << "," << tilt.y;
  }
}

// A ceiling at height h whose half x < 0 has radiance 1, the rest 0: E(x) = π/2 (1 − x/√(x²+h²)),
// so E = π/2 and dE/dx = −π/(2h) at x = 0, and dE/dy = 0. 50 rings of 160 sectors put the edge on
// the boundaries of sectors 40 and 120 (φ = 90° and 270°), so every stratum is wholly lit or dark
// whatever its jitter, and E is π/(MN) times the float count MN/2: π/2 within 3 roundings, as for
// the uniform sky (a stratum's weight 0.5% off is 3·10⁴ times that). Ward & Heckbert's translation
// gradient finds the gradient within 5% (the boundaries' distances are the nearer of two jittered
// rays').
TEST(WardHemisphere, TheTranslationGradientFollowsAnEdgeOfLight) {
  const float h = 2.0f;
  const WardStrata strata = wardStrata(8000);
  ASSERT_EQ(strata.phi % 4, 0);  // φ = 90° and 270° fall on sector boundaries
  const gpu::IrradianceRecord r = sampleField(strata, 9, [&](const glm::vec3& w) {
    const glm::vec3 hit = w * (h / w.z);
    return HemisphereSample{glm::vec3(hit.x < 0 ? 1.0f : 0.0f), h / w.z};
  });
  const glm::vec3 gradient(r.translation[0]);
  EXPECT_NEAR(r.irradiance.x, kPi / 2, 3 * kUnitRoundoff * kPi / 2);
  EXPECT_NEAR(gradient.x, -kPi / (2 * h), 0.05 * kPi / (2 * h));
  EXPECT_NEAR(gradient.y, 0.0, 0.05 * kPi / (2 * h));
  EXPECT_NEAR(gradient.z, 0.0, 1e-6);
}

}  // namespace
}  // namespace gib::rt
