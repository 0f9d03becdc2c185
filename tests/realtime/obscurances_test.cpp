// `obscurances` end to end (book Ch. 10): the bundle estimate of W against closed forms (an open
// plane, two parallel planes, a closed box) and against the reference's Embree estimate (a closed
// box, the Cornell box: the normalisation is unbiased), spectral against scalar, W's error falling
// with the number of bundles, the final image against the full reference, the light weighting,
// and bad parameters.
#include "realtime/techniques/obscurances/obscurances_technique.h"

#include "common/input_error.h"
#include "metrics/image_metrics.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "reference/obscurance_estimator.h"
#include "reference/progressive_renderer.h"
#include "reference/rng.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"
#include "support/gl_test_context.h"
#include "support/inward_box.h"
#include "support/statistical_test.h"
#include "support/technique_frame.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <functional>
#include <map>

namespace gib::rt {
namespace {

// The family of this file's statistical tests: α = 0.01 over n = 17 tests (the open plane; the
// parallel planes, two fall-offs; the closed box's six walls; the Cornell box's eight meshes).
constexpr test::TestFamily kFamily(0.01, 17);
// Independent runs (seeds) of the technique whose spread gives its estimates' standard error.
constexpr int kSeeds = 5;

class ObscurancesTest : public test::GlTest {};

const TechniqueInfo& info() {
  return findTechnique("obscurances");
}

ParameterValues parameters(const std::vector<std::string>& set) {
  return parseParameters(info().parameters, set, "technique 'obscurances'");
}

// One prepared technique's obscurances map.
struct MapRun {
  std::vector<glm::vec3> w;
  atlas::AtlasTexels texels;
  std::vector<atlas::AtlasTriangle> triangles;
};

MapRun buildMap(const scene::Scene& scene, const std::vector<std::string>& set) {
  GpuScene gpu(scene, 16, 16);
  ObscurancesTechnique technique(parameters(set));
  technique.prepare(gpu, 16, 16);
  return {technique.obscuranceMap(), technique.atlasTexels(), technique.atlasTriangles()};
}

// The area-weighted mean of W's luminance over the covered texels that `select` accepts.
double areaMean(const MapRun& run, const std::function<bool(const atlas::AtlasTexel&)>& select) {
  double sum = 0, area = 0;
  for (std::size_t i = 0; i < run.texels.texels.size(); ++i) {
    const atlas::AtlasTexel& t = run.texels.texels[i];
    if (!(t.area > 0) || !select(t)) continue;
    sum += double(t.area) * double(scene::luminance(run.w[i]));
    area += t.area;
  }
  return area > 0 ? sum / area : std::nan("");
}

struct SeedStatistics {
  double mean = 0, standard_error = 0;
};

// The mean over kSeeds independent runs of `measure` and its standard error (K − 1 dof).
SeedStatistics overSeeds(const std::function<double(std::uint32_t seed)>& measure) {
  std::vector<double> values;
  for (std::uint32_t seed = 0; seed < kSeeds; ++seed) values.push_back(measure(seed));
  SeedStatistics s;
  for (double v : values) s.mean += v / kSeeds;
  double squares = 0;
  for (double v : values) squares += (v - s.mean) * (v - s.mean);
  s.standard_error = std::sqrt(squares / (kSeeds - 1) / kSeeds);
  return s;
}

std::string seedSetting(std::uint32_t seed) {
  return "seed=" + std::to_string(seed);
}

// A scene of the given quads (one mesh each, one Lambertian material of albedo `albedo`), with
// the Cornell box's camera and a small emitter far away so the scene has a light.
scene::Scene quadScene(const std::vector<std::array<glm::vec3, 4>>& quads, float albedo = 0.5f) {
  scene::Scene scene = scene::loadScene("cornell", {});
  scene.meshes.clear();
  scene.materials.clear();
  scene.spot_lights.clear();
  scene.directional_lights.clear();
  scene::Material m;
  m.name = "grey";
  m.diffuse = scene::Rgb(albedo);
  scene.materials.push_back(m);
  for (const auto& q : quads) {
    scene::Mesh mesh;
    mesh.name = "quad" + std::to_string(scene.meshes.size());
    scene::appendQuad(mesh, q[0], q[1], q[2], q[3]);
    scene.meshes.push_back(mesh);
  }
  return scene;
}

TEST_F(ObscurancesTest, AnOpenPlaneHasObscuranceOne) {
  const scene::Scene plane = quadScene({{{{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}}}});
  const SeedStatistics w = overSeeds([&](std::uint32_t seed) {
    const MapRun run = buildMap(plane, {"mode=scalar", "directions=16", "peel_resolution=64",
                                        "atlas=64", seedSetting(seed)});
    return areaMean(run, [](const atlas::AtlasTexel&) { return true; });
  });
  EXPECT_TRUE(kFamily.tTest(w.mean, 1.0, w.standard_error, kSeeds - 1));
}

// A point on a plane at height h under an infinite parallel plane (facing it): with μ = cos θ
// the ray reaches the other plane at d = h/μ, so W = (1/π)∫ρ(h/μ) cos θ dω = 2∫₀¹ ρ(h/μ) μ dμ.
// With c = h/d_max < 1: ρ = 1 for μ < c, and √(c/μ) or 0 above: W = c² + (4/3)√c(1 − c^{3/2}) =
// (4/3)√c − c²/3 for the square-root fall-off, W = c² for ambient occlusion.
double parallelPlanesObscurance(scene::ObscuranceFalloff falloff, double c) {
  if (c >= 1) return 1;
  return falloff == scene::ObscuranceFalloff::kSqrt ? 4.0 / 3.0 * std::sqrt(c) - c * c / 3.0
                                                    : c * c;
}

TEST_F(ObscurancesTest, ParallelPlanesMatchTheClosedForm) {
  constexpr float kHalf = 10, kHeight = 1, kMaxDistance = 2;
  const scene::Scene planes = quadScene({
      {{{-kHalf, 0, -kHalf}, {-kHalf, 0, kHalf}, {kHalf, 0, kHalf}, {kHalf, 0, -kHalf}}},
      {{{-kHalf, kHeight, -kHalf},
        {kHalf, kHeight, -kHalf},
        {kHalf, kHeight, kHalf},
        {-kHalf, kHeight, kHalf}}},
  });
  const float fraction = kMaxDistance / scene::sceneDiagonal(planes);
  // A ray shorter than d_max ends within d_max of its start, sideways: texels that far inside the
  // planes' edges see them as infinite.
  const auto central = [&](const atlas::AtlasTexel& t) {
    return std::abs(t.position.x) < kHalf - kMaxDistance - 0.5f &&
           std::abs(t.position.z) < kHalf - kMaxDistance - 0.5f;
  };
  for (const auto falloff :
       {scene::ObscuranceFalloff::kSqrt, scene::ObscuranceFalloff::kAmbientOcclusion}) {
    const SeedStatistics w = overSeeds([&](std::uint32_t seed) {
      const MapRun run = buildMap(
          planes, {"mode=scalar", "falloff=" + std::string(scene::obscuranceFalloffName(falloff)),
                   "d_max=" + std::to_string(fraction), "directions=32", "peel_resolution=192",
                   "atlas=64", seedSetting(seed)});
      return areaMean(run, central);
    });
    EXPECT_TRUE(kFamily.tTest(w.mean, parallelPlanesObscurance(falloff, kHeight / kMaxDistance),
                              w.standard_error, kSeeds - 1))
        << scene::obscuranceFalloffName(falloff);
  }
}

// The inside of a closed cube [−1, 1]³: six quads facing inwards, a mesh each.
scene::Scene closedBox() {
  const auto faces = test::inwardBoxFaces(glm::vec3(-1), glm::vec3(1));
  return quadScene(std::vector<std::array<glm::vec3, 4>>(faces.begin(), faces.end()));
}

TEST_F(ObscurancesTest, AClosedBoxIsFullyOccludedWithinItsDiagonal) {
  // Every ray from a wall meets another wall nearer than the diagonal: the step fall-off gives 0.
  // With one layer peeled the wall behind is never found: a patch whose occluder lies beyond the
  // last layer gives no sample, never a wrong "open" (which would make W positive).
  for (const char* max_layers : {"max_layers=16", "max_layers=1"}) {
    const MapRun run =
        buildMap(closedBox(), {"mode=scalar", "falloff=ambient_occlusion", "d_max=1.01",
                               "directions=16", "peel_resolution=64", "atlas=64", max_layers});
    int covered = 0;
    for (std::size_t i = 0; i < run.texels.texels.size(); ++i)
      if (run.texels.texels[i].area > 0) {
        ++covered;
        EXPECT_EQ(run.w[i], glm::vec3(0.0f)) << "texel " << i << ", " << max_layers;
      }
    EXPECT_GT(covered, 100);
  }
}

// The mean of W over each mesh (area-weighted), by the technique over kSeeds seeds and by the
// reference's Embree estimate at uniform points on the mesh, and a test of each difference.
void expectMeshMeansAgreeWithEmbree(const scene::Scene& scene, const std::vector<std::string>& set,
                                    const scene::ObscuranceDefinition& definition) {
  std::map<std::uint32_t, std::vector<double>> gpu;  // mesh → its mean per seed
  for (std::uint32_t seed = 0; seed < kSeeds; ++seed) {
    std::vector<std::string> with_seed = set;
    with_seed.push_back(seedSetting(seed));
    const MapRun run = buildMap(scene, with_seed);
    for (std::uint32_t mesh = 0; mesh < scene.meshes.size(); ++mesh)
      gpu[mesh].push_back(areaMean(run, [&](const atlas::AtlasTexel& t) {
        return run.triangles[std::size_t(t.triangle)].mesh == mesh;
      }));
  }
  const ref::ObscuranceEstimator estimator(scene, definition);
  const std::vector<atlas::AtlasTriangle> triangles = atlas::atlasTriangles(scene);
  constexpr int kPoints = 4096;
  for (std::uint32_t mesh = 0; mesh < scene.meshes.size(); ++mesh) {
    // Uniform points on the mesh: a triangle by area, a point in it.
    std::vector<const atlas::AtlasTriangle*> own;
    std::vector<double> cdf;
    double area = 0;
    for (const atlas::AtlasTriangle& t : triangles)
      if (t.mesh == mesh && t.area > 0) {
        own.push_back(&t);
        area += t.area;
        cdf.push_back(area);
      }
    ref::SampleStream stream(1234, mesh, 0);
    std::vector<ref::ObscurancePoint> points;
    for (int i = 0; i < kPoints; ++i) {
      const double pick = stream.next() * area;
      const std::size_t k =
          std::size_t(std::lower_bound(cdf.begin(), cdf.end(), pick) - cdf.begin());
      const atlas::AtlasTriangle& t = *own[std::min(k, own.size() - 1)];
      float u = float(stream.next()), v = float(stream.next());
      if (u + v > 1) u = 1 - u, v = 1 - v;
      points.push_back({t.p[0] + u * (t.p[1] - t.p[0]) + v * (t.p[2] - t.p[0]), t.normal});
    }
    const std::vector<ref::ObscuranceEstimate> estimates =
        ref::estimateObscurances(estimator, points, 4, 99);
    double mean = 0, squares = 0;
    std::vector<double> values;
    for (const ref::ObscuranceEstimate& e : estimates)
      values.push_back(double(scene::luminance(glm::vec3(e.mean))));
    for (double x : values) mean += x / kPoints;
    for (double x : values) squares += (x - mean) * (x - mean);
    const double embree_se = std::sqrt(squares / (kPoints - 1) / kPoints);
    double gpu_mean = 0, gpu_squares = 0;
    for (double x : gpu[mesh]) gpu_mean += x / kSeeds;
    for (double x : gpu[mesh]) gpu_squares += (x - gpu_mean) * (x - gpu_mean);
    const double gpu_se = std::sqrt(gpu_squares / (kSeeds - 1) / kSeeds);
    // The difference's standard error is dominated by the technique's (K − 1 dof): testing with
    // K − 1 degrees of freedom is conservative.
    EXPECT_TRUE(kFamily.tTest(gpu_mean - mean, 0.0, std::hypot(gpu_se, embree_se), kSeeds - 1))
        << scene.meshes[mesh].name << ": bundles " << gpu_mean << ", Embree " << mean;
  }
}

TEST_F(ObscurancesTest, AClosedBoxAgreesWithTheEmbreeEstimate) {
  // d_max beyond the box's diagonal: every ray is occluded, and ρ(d) = √(d/d_max) weighs it.
  scene::ObscuranceDefinition definition;
  definition.mode = scene::ObscuranceMode::kScalar;
  definition.d_max_fraction = 1.01f;
  expectMeshMeansAgreeWithEmbree(
      closedBox(), {"mode=scalar", "d_max=1.01", "directions=32", "peel_resolution=96", "atlas=64"},
      definition);
}

TEST_F(ObscurancesTest, TheBundleEstimateIsUnbiasedOnTheCornellBox) {
  scene::ObscuranceDefinition definition;              // √, d_max 0.25: the defaults
  definition.mode = scene::ObscuranceMode::kSpectral;  // the technique's default
  expectMeshMeansAgreeWithEmbree(scene::loadScene("cornell", {}),
                                 {"directions=32", "peel_resolution=128", "atlas=64"}, definition);
}

TEST_F(ObscurancesTest, SpectralWithEqualAlbedosIsScalarTimesTheAlbedo) {
  scene::Scene scene = scene::loadScene("cornell", {});
  constexpr float kAlbedo = 0.6f;
  for (scene::Material& m : scene.materials) m.diffuse = scene::Rgb(kAlbedo);
  const std::vector<std::string> common = {"directions=8", "peel_resolution=64", "atlas=64"};
  auto with = [&](std::string mode) {
    std::vector<std::string> set = common;
    set.push_back("mode=" + mode);
    return buildMap(scene, set);
  };
  const MapRun scalar = with("scalar"), spectral = with("spectral");
  for (std::size_t i = 0; i < scalar.w.size(); ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(spectral.w[i][c], kAlbedo * scalar.w[i][c], 1e-5f * (1.0f + scalar.w[i][c]))
          << "texel " << i;
}

TEST_F(ObscurancesTest, ObscuranceErrorFallsAsBundlesGrow) {
  const scene::Scene cornell = scene::loadScene("cornell", {});
  constexpr int kSize = 32;
  ref::RenderSettings settings;
  settings.width = settings.height = kSize;
  settings.spp = 256;
  settings.pixel_sampling = ref::PixelSampling::kCenter;
  settings.obscurance = scene::ObscuranceDefinition{};
  const ref::RenderResult reference = ref::renderReference(cornell, settings);
  auto error = [&](int directions) {
    const TechniqueRunResult run = test::renderOneFrame(
        cornell, "obscurances",
        {"output=obscurance", "mode=scalar", "directions=" + std::to_string(directions), "atlas=64",
         "peel_resolution=128"},
        kSize);
    return metrics::computeMse(reference.mean, run.image).value;
  };
  const double few = error(2), many = error(64);
  EXPECT_LT(many, 0.5 * few) << "2 bundles: MSE " << few << ", 64 bundles: MSE " << many;
}

TEST_F(ObscurancesTest, AddsIndirectLightThatBringsTheImageCloserToTheFullReference) {
  const scene::Scene cornell = scene::loadScene("cornell", {});
  constexpr int kSize = 32;
  const ref::RenderResult full = test::renderClassReference(cornell, kSize, 256, {});
  const auto mse = [&](const std::string& technique, const std::vector<std::string>& set) {
    return metrics::computeMse(full.mean,
                               test::renderOneFrame(cornell, technique, set, kSize).image)
        .value;
  };
  const double direct = mse("direct", {});
  const double obscurances =
      mse("obscurances", {"directions=16", "peel_resolution=96", "atlas=64"});
  EXPECT_LT(obscurances, direct) << "direct " << direct << ", obscurances " << obscurances;
}

TEST_F(ObscurancesTest, LightWeightingMovesTheAmbientLightTowardsTheLight) {
  const scene::Scene cornell = scene::loadScene("cornell", {});
  constexpr int kSize = 32;
  const auto ambient = [&](const std::string& weighting) {
    const TechniqueRunResult run = test::renderOneFrame(
        cornell, "obscurances",
        {"light_weighting=" + weighting, "directions=8", "peel_resolution=64", "atlas=64"}, kSize);
    for (const AuxiliaryImage& a : run.auxiliary)
      if (a.name == "ambient") return a.image;
    ADD_FAILURE() << "no ambient image";
    return image::Image(kSize, kSize);
  };
  const image::Image plain = ambient("none"), weighted = ambient("distance");
  // Rows near the top of the image are the ceiling, by the light; rows near the bottom the floor.
  const auto rowsRatio = [&](int y0, int y1) {
    double a = 0, b = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = kSize / 4; x < 3 * kSize / 4; ++x) {
        a += weighted.pixel(x, y)[1];
        b += plain.pixel(x, y)[1];
      }
    return a / b;
  };
  EXPECT_GT(rowsRatio(1, 4), 1.0);
  EXPECT_LT(rowsRatio(kSize - 4, kSize - 1), 1.0);
}

TEST_F(ObscurancesTest, RefusesBadParameters) {
  for (const char* bad :
       {"d_max=0", "d_max=-1", "directions=0", "peel_resolution=4", "max_layers=0", "atlas=7",
        "mode=colour", "falloff=linear", "output=radiance", "light_weighting=yes"})
    EXPECT_THROW(parameters({std::string(bad)}), InputError) << bad;
  EXPECT_FLOAT_EQ(float(parameters({}).number("d_max")),
                  scene::ObscuranceDefinition::kDefaultObscuranceDistanceFraction);
}

TEST_F(ObscurancesTest, OutputObscuranceAsksForTheObscuranceReference) {
  ObscurancesTechnique final_image(parameters({}));
  EXPECT_FALSE(final_image.imageObscurance().has_value());
  ObscurancesTechnique w(parameters({"output=obscurance", "mode=scalar", "d_max=0.5"}));
  ASSERT_TRUE(w.imageObscurance().has_value());
  EXPECT_EQ(w.imageObscurance()->mode, scene::ObscuranceMode::kScalar);
  EXPECT_FLOAT_EQ(w.imageObscurance()->d_max_fraction, 0.5f);
}

}  // namespace
}  // namespace gib::rt
