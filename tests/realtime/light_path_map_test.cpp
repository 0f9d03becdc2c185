// `light_path_map` (book §8.4): the CPU preprocessing (entry points, clusters, walks), one entry
// point's pane against the closed form, clustering's sums, convergence to the reference without
// clustering, lights moved without preprocessing again, memory, determinism and bad input.
#include "realtime/techniques/light_path_map/light_path_map_technique.h"

#include "common/input_error.h"
#include "metrics/image_metrics.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/technique_runner.h"
#include "reference/embree_scene.h"
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"
#include "support/form_factor.h"
#include "support/gl_test_context.h"
#include "support/inward_box.h"
#include "support/render_statistics.h"
#include "support/statistical_test.h"
#include "support/technique_frame.h"

#include <gtest/gtest.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gib::rt {
namespace {

using test::imageMean;
using test::pointToPolygonFormFactor;

constexpr double kPi = std::numbers::pi;

// A correct technique fails one of this file's four statistical tests (the entry points' share of
// each triangle, the walks' mean length, the first bounce's pane against its form factor, and the
// converged image mean against the reference) with probability 1%.
constexpr test::TestFamily kFamily(0.01, 4);

// Two parallel unit squares one unit apart, face to face, both diffuse.
constexpr float kBottomAlbedo = 0.6f, kTopAlbedo = 0.5f;
scene::Scene facingPatches() {
  scene::Material top, bottom;
  top.name = "top";
  top.diffuse = scene::Rgb(kTopAlbedo);
  bottom.name = "bottom";
  bottom.diffuse = scene::Rgb(kBottomAlbedo);
  return test::facingUnitSquares(top, bottom);
}

TechniqueServices embree() {
  return {ref::embreeRayCasterFactory()};
}

// A prepared technique on its own GPU scene, rendered for frames as the runner does.
struct Prepared {
  Prepared(const scene::Scene& s, const LightPathMapSettings& settings, int width, int height)
      : scene(s), gpu(scene, width, height), technique(settings), target(width, height) {
    technique.provide(embree());
    technique.prepare(gpu, width, height);
  }
  image::Image render() {
    gl::PassProfiler profiler;
    Frame frame{target, profiler, 0, 1};
    target.clear(0, 0, 0);
    technique.render(frame);
    return target.read();
  }
  scene::Scene scene;
  GpuScene gpu;
  LightPathMapTechnique technique;
  RenderTarget target;
};

// The book's sampling: density 1/S. Triangles of areas 1 and 3 receive a quarter and three
// quarters of the points (the second's count is binomial). Every point lies inside its triangle.
TEST(LightPathMapEntryPoints, AreUniformOverTheSurfaceArea) {
  std::vector<atlas::AtlasTriangle> triangles(2);
  triangles[0].p = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 0, 2)};  // area 1
  triangles[1].p = {glm::vec3(0, 1, 0), glm::vec3(3, 1, 0), glm::vec3(0, 1, 2)};  // area 3
  triangles[0].area = 1;
  triangles[1].area = 3;
  const std::vector<lpm::EntryPoint> points = lpm::sampleEntryPoints(triangles, 20000, 7);
  ASSERT_EQ(points.size(), 20000u);
  std::size_t second = 0;
  for (const lpm::EntryPoint& p : points) {
    const atlas::AtlasTriangle& t = triangles[std::size_t(p.triangle)];
    const glm::vec3 e1 = t.p[1] - t.p[0], e2 = t.p[2] - t.p[0], d = p.position - t.p[0];
    const float u = d.x / e1.x, v = d.z / e2.z;  // both triangles are right-angled at p[0]
    EXPECT_GE(u, 0.0f);
    EXPECT_GE(v, 0.0f);
    EXPECT_LE(u + v, 1.0f + 1e-5f);
    EXPECT_EQ(p.position.y, t.p[0].y);
    second += p.triangle == 1;
  }
  EXPECT_TRUE(kFamily.binomial(second, points.size(), 0.75));
  EXPECT_EQ(lpm::sampleEntryPoints(triangles, 100, 7)[42].position, points[42].position);
}

// The object-median kd-tree: clusters equally large to within one point, each a compact group
// (here the points of a line: every cluster is a contiguous run), the same every call.
TEST(LightPathMapEntryPoints, ClustersAreEquallyLargeAndCompact) {
  std::vector<lpm::EntryPoint> points(1000);
  for (int i = 0; i < 1000; ++i) points[std::size_t(i)].position = {float((i * 7919) % 1000), 0, 0};
  for (int clusters : {1, 3, 16, 256, 1000}) {
    const std::vector<int> cluster_of = lpm::clusterEntryPoints(points, clusters);
    std::vector<int> size(std::size_t(clusters), 0);
    std::vector<float> lo(std::size_t(clusters), 1e9f), hi(std::size_t(clusters), -1e9f);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const std::size_t c = std::size_t(cluster_of[i]);
      ++size[c];
      lo[c] = std::min(lo[c], points[i].position.x);
      hi[c] = std::max(hi[c], points[i].position.x);
    }
    const auto [smallest, largest] = std::minmax_element(size.begin(), size.end());
    EXPECT_LE(*largest - *smallest, 1) << clusters << " clusters";
    EXPECT_GE(*smallest, 1);
    for (int c = 0; c < clusters; ++c)  // contiguous: the span holds exactly its points
      EXPECT_EQ(hi[std::size_t(c)] - lo[std::size_t(c)] + 1, float(size[std::size_t(c)]));
    EXPECT_EQ(cluster_of, lpm::clusterEntryPoints(points, clusters));
  }
}

// K-means from the kd-tree's clusters never raises the sum of squared distances to the cluster
// means (Lloyd's iterations), here over the Cornell box's entry points, where the kd-tree's
// boxes straddle the box's corners; every index is a cluster; the same every call.
TEST(LightPathMapEntryPoints, KMeansLowersTheClusteringCostAndIsDeterministic) {
  const std::vector<atlas::AtlasTriangle> triangles =
      atlas::atlasTriangles(scene::loadScene("cornell", {}));
  const std::vector<lpm::EntryPoint> points = lpm::sampleEntryPoints(triangles, 1024, 5);
  const std::vector<int> kdtree = lpm::clusterEntryPoints(points, 32);
  const std::vector<int> kmeans = lpm::clusterEntryPointsKMeans(points, 32, 20);
  const double kdtree_cost = lpm::clusteringCost(points, kdtree, 32);
  const double kmeans_cost = lpm::clusteringCost(points, kmeans, 32);
  std::printf("clustering cost: kd-tree %.3f, K-means %.3f\n", kdtree_cost, kmeans_cost);
  EXPECT_LT(kmeans_cost, kdtree_cost);
  for (int c : kmeans) {
    EXPECT_GE(c, 0);
    EXPECT_LT(c, 32);
  }
  EXPECT_EQ(kmeans, lpm::clusterEntryPointsKMeans(points, 32, 20));
  EXPECT_EQ(lpm::clusterEntryPointsKMeans(points, 32, 0), kdtree);  // no iteration: the start
}

// Russian roulette with continuation 𝓛(albedo): in a closed grey box of albedo 0.5 a walk visits
// 1/(1 − 0.5) = 2 points on average (geometric; variance 2 per walk, so over 2 × 10 000 walks the
// mean's standard error is 0.01). Every light's intensity is S·share·ρ/π (a grey albedo's ρ/𝓛(ρ)
// is 1).
TEST(LightPathMapWalks, PathLengthsFollowTheAlbedo) {
  scene::Scene s;
  s.name = "grey_box";
  scene::Material grey;
  grey.name = "grey";
  grey.diffuse = scene::Rgb(0.5f);
  s.materials = {grey};
  scene::Mesh box;  // the unit cube, every face's normal inwards
  for (const auto& q : test::inwardBoxFaces(glm::vec3(0), glm::vec3(1)))
    scene::appendQuad(box, q[0], q[1], q[2], q[3]);
  s.meshes = {box};
  const std::vector<atlas::AtlasTriangle> triangles = atlas::atlasTriangles(s);
  double area = 0;
  for (const auto& t : triangles) area += t.area;
  const std::vector<lpm::EntryPoint> entries = lpm::sampleEntryPoints(triangles, 10000, 3);
  const std::vector<int> clusters = lpm::clusterEntryPoints(entries, 16);
  const auto caster = ref::embreeRayCasterFactory()(s);
  const lpm::LightWalks walks =
      lpm::traceLightWalks(*caster, s, triangles, entries, clusters, 2, area, 3);
  EXPECT_TRUE(kFamily.zTest(double(walks.path_vertices) / 20000.0, 2.0, std::sqrt(2.0 / 20000)));
  const float entry_intensity = float(area) * 0.5f / std::numbers::pi_v<float>;
  for (const lpm::VirtualLight& v : walks.lights) {
    const bool entry = std::abs(v.intensity.x - entry_intensity) < 1e-4f * entry_intensity;
    if (!entry) {
      EXPECT_NEAR(v.intensity.x, 0.5f * entry_intensity, 1e-4f * entry_intensity);
    }
  }
  EXPECT_TRUE(std::is_sorted(walks.lights.begin(), walks.lights.end(),
                             [](const auto& a, const auto& b) { return a.cluster < b.cluster; }));
}

class LightPathMapTest : public test::GlTest {};

// Small maps for tests: a 64² atlas, 64² virtual-light shadow maps, one light sample per light.
LightPathMapSettings smallSettings(int entry_points, int clusters, int panes_used) {
  LightPathMapSettings settings;
  settings.entry_points = entry_points;
  settings.clusters = clusters;
  settings.panes_used = panes_used;
  settings.atlas_resolution = 64;
  settings.vpl_shadow_map_size = 64;
  settings.light_samples = 1;
  return settings;
}

// One cluster holding every entry point, walks cut after the entry point (the first indirect
// bounce): the pane at each texel of the top square is the sum over the entry points on the
// bottom square of S·(ρ_b/π)·cos θ_e·cos θ_x/d²·ρ_t/π. (a) The GPU's pane equals that sum over the
// same entry points evaluated on the CPU, texel by texel, within 2% (half-float storage, the
// texel-area distance offset). (b) Its mean over the top square estimates ρ_b·ρ_t·F/π with F the
// point-to-area form factor to the bottom square (Lambert's formula) averaged over the texels:
// the mean of the n per-entry contributions (zero for an entry on the top square), by a t test on
// its standard error with n − 1 degrees of freedom.
TEST_F(LightPathMapTest, FirstBouncePaneMatchesTheFormFactor) {
  LightPathMapSettings settings = smallSettings(1024, 1, 1);
  settings.vpl_shadow_map_size = 256;
  settings.max_walk_vertices = 1;
  Prepared p(facingPatches(), settings, 16, 16);
  const std::vector<glm::vec3> pane = p.technique.pane(0);
  const atlas::AtlasTexels& texels = p.technique.atlasTexels();
  const std::vector<lpm::EntryPoint>& entries = p.technique.entryPoints();
  const double n = double(entries.size()), total_area = 2.0;
  const std::vector<glm::dvec3> bottom = {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}};

  std::vector<double> per_entry(entries.size(), 0.0);  // each entry's mean over the top texels
  double area = 0, gpu_mean = 0, expected_mean = 0;
  int checked = 0;
  for (std::size_t i = 0; i < texels.texels.size(); ++i) {
    const atlas::AtlasTexel& t = texels.texels[i];
    if (t.area <= 0 || t.triangle >= 2) continue;  // triangles 0 and 1 are the top square
    double cpu = 0;
    for (std::size_t e = 0; e < entries.size(); ++e) {
      if (entries[e].triangle < 2) continue;  // on the top square
      const glm::dvec3 d = glm::dvec3(t.position) - glm::dvec3(entries[e].position);
      const double d2 = glm::dot(d, d);
      const double contribution = total_area * kBottomAlbedo / kPi * (d.y / std::sqrt(d2)) *
                                  (d.y / std::sqrt(d2)) / d2 * kTopAlbedo / kPi;
      cpu += contribution;
      per_entry[e] += t.area * contribution;
    }
    EXPECT_NEAR(pane[i].g, cpu, 0.02 * cpu) << "texel " << i;
    area += t.area;
    gpu_mean += t.area * pane[i].g;
    expected_mean += t.area * kBottomAlbedo * kTopAlbedo / kPi *
                     pointToPolygonFormFactor(glm::dvec3(t.position), {0, -1, 0}, bottom);
    ++checked;
  }
  ASSERT_GT(checked, 500);
  gpu_mean /= area * n;
  expected_mean /= area;
  double mean = 0, square = 0;
  for (double& c : per_entry) {
    c /= area;
    mean += c / n;
    square += c * c / n;
  }
  const double standard_error = std::sqrt((square - mean * mean) / (n - 1));
  std::printf("pane mean %.6f, closed form %.6f, standard error %.6f\n", gpu_mean, expected_mean,
              standard_error);
  EXPECT_TRUE(kFamily.tTest(gpu_mean, expected_mean, standard_error, n - 1));
}

// A cluster's pane is the sum of its members' panes (the same walks whatever the clustering:
// each path draws from its entry point's index), and its weight the mean of its members'
// irradiance, here on the chamber under its spot light.
TEST_F(LightPathMapTest, ClusterPaneAndWeightAreTheMembersSumAndMean) {
  const scene::Scene chamber = scene::loadScene("chamber", {});
  LightPathMapSettings settings = smallSettings(16, 16, 16);
  Prepared single(chamber, settings, 16, 16);
  settings.clusters = settings.panes_used = 4;
  Prepared grouped(chamber, settings, 16, 16);
  grouped.render();
  const std::vector<int>& cluster_of = grouped.technique.clusterOfEntry();
  const std::vector<glm::vec3>& irradiance = grouped.technique.entryIrradiance();
  for (int c = 0; c < 4; ++c) {
    std::vector<glm::vec3> sum(grouped.technique.pane(c).size(), glm::vec3(0.0f));
    glm::vec3 weight(0.0f);
    int members = 0;
    for (std::size_t e = 0; e < cluster_of.size(); ++e) {
      if (cluster_of[e] != c) continue;
      const std::vector<glm::vec3> member =
          single.technique.pane(single.technique.clusterOfEntry()[e]);
      for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += member[i];
      weight += irradiance[e];
      ++members;
    }
    EXPECT_EQ(members, 4);
    const glm::vec3 expected_weight = weight / float(members);
    EXPECT_NEAR(grouped.technique.clusterWeights()[std::size_t(c)].r, expected_weight.r,
                1e-5f * expected_weight.r + 1e-9f);
    const std::vector<glm::vec3> pane = grouped.technique.pane(c);
    double total = 0, difference = 0;
    for (std::size_t i = 0; i < sum.size(); ++i) {
      total += sum[i].r;
      difference += std::abs(double(pane[i].r) - double(sum[i].r));
    }
    EXPECT_GT(total, 0.0);
    EXPECT_LT(difference, 2e-3 * total) << "cluster " << c;  // half-float rounding
  }
  // The entry points that face the spot light get light; the weights are not all zero.
  EXPECT_GT(std::count_if(irradiance.begin(), irradiance.end(),
                          [](const glm::vec3& e) { return e.r > 0; }),
            0);
}

// Lights move without new preprocessing: the chamber's spot moved by an offset at run time gives
// the image of a technique prepared with the spot already there (the maps do not depend on the
// lights), to float precision.
TEST_F(LightPathMapTest, AMovedLightNeedsNoNewPreprocessing) {
  const LightPathMapSettings settings = smallSettings(64, 8, 4);
  Prepared moved_at_run_time(scene::loadScene("chamber", {}), settings, 32, 24);
  const glm::vec3 offset(1.5f, -0.5f, 2.0f);
  moved_at_run_time.technique.setLightOffset(offset);
  const image::Image a = moved_at_run_time.render();
  Prepared moved_in_scene(
      scene::loadScene("chamber", {"light_position=1.5,6.1,5.5", "light_target=1.9,-0.5,9.5"}),
      settings, 32, 24);
  const image::Image b = moved_in_scene.render();
  const image::Image before = Prepared(scene::loadScene("chamber", {}), settings, 32, 24).render();
  double sum = 0, difference = 0, change = 0;
  for (std::size_t i = 0; i < a.data().size(); ++i) {
    sum += b.data()[i];
    difference += std::abs(a.data()[i] - b.data()[i]);
    change += std::abs(before.data()[i] - b.data()[i]);
  }
  EXPECT_LT(difference, 1e-4 * sum);
  EXPECT_GT(change, 0.05 * sum);  // the light did move
}

// GL reports the pane array's size: clusters × atlas² texels of RGBA16F (the book's 128 MB at
// 256 panes of 256²; here 8 of 64²).
TEST_F(LightPathMapTest, PaneMemoryIsWhatGlAllocated) {
  const LightPathMapSettings settings = smallSettings(64, 8, 8);
  Prepared p(scene::loadScene("cornell", {}), settings, 16, 16);
  EXPECT_EQ(p.technique.preprocessing().pane_bytes, 8 * 64 * 64 * 8);
}

TechniqueRunSettings smallRun() {
  TechniqueRunSettings settings;
  settings.width = 32;
  settings.height = 32;
  settings.warmup_frames = 0;
  settings.frames = 1;
  settings.context.debug = true;
  settings.services = embree();
  return settings;
}

TechniqueRunResult runCornell(const std::vector<std::string>& set) {
  const TechniqueInfo& info = findTechnique("light_path_map");
  return runTechnique(scene::loadScene("cornell", {}), info,
                      parseParameters(info.parameters, set, "technique"), smallRun());
}

// The light the distance offset takes away, as a fraction of the indirect light, at most. A
// virtual light adds ρ/π·I·cos θ/(d² + A/π) (atlas_light.frag.glsl), A a texel's area, where
// the light itself has 1/d²: the offset keeps a receiver beside the light finite and takes light
// away within δ = √(A/π) of it. Only light exchanged across an edge between two surfaces comes
// that close (within one plane cos θ is 0): a receiver at distance y from the edge loses about
// min(1, δ²/y²) of what the surface across the edge sends it, which over a surface of width L
// averages 2δ/L. A is the surfaces' area over the atlas's covered texels, L the box's side. (The
// panes' half floats round each value by 2⁻¹¹ either way, which averages out.)
double distanceOffsetLoss(const scene::Scene& scene, double covered_texels) {
  double area = 0;
  glm::vec3 lower(1e30f), upper(-1e30f);
  for (const atlas::AtlasTriangle& t : atlas::atlasTriangles(scene)) {
    area += t.area;
    for (const glm::vec3& p : t.p) {
      lower = glm::min(lower, p);
      upper = glm::max(upper, p);
    }
  }
  const glm::vec3 extent = upper - lower;
  const double side = std::max({extent.x, extent.y, extent.z});
  return 2 * std::sqrt(area / covered_texels / kPi) / side;
}

// Without clustering (a pane per entry point, all used) the maps' own image (output=indirect,
// two or more bounces) estimates the reference of that path class, unbiased but for the
// distance offset (above), with a noise that falls as entry points grow. Twelve seeds of 256
// entry points (as long as four of 1024 and one of 128 took, with eleven degrees of freedom for
// the spread instead of three): (a) their mean image (3072 entry points in all) is closer to the
// reference than one seed's, by relMSE less the reference's noise; (b) the mean of their image
// means agrees with the reference's: the difference, over its standard error (the seeds' spread
// and the reference's variance layer, 1024 spp in 16 replicas), by a t test with their
// Welch–Satterthwaite degrees of freedom (about 11), allowing on the low side the offset's loss.
// One seed's image mean has a standard deviation of ~16% here, so (b) sees a bias of ~18% or more:
// a bounce left out of the walks (the third and later carry half of this class), not a few per cent
// of scale, which would take twenty times the seeds.
TEST(LightPathMap, ConvergesToTheReferenceWithoutClustering) {
  constexpr int kSeeds = 12, kEntryPoints = 256;
  const scene::Scene scene = scene::loadScene("cornell", {});
  ref::RenderSettings reference_settings;
  reference_settings.width = 32;
  reference_settings.height = 32;
  reference_settings.spp = 1024;
  reference_settings.replicas = 16;
  reference_settings.path_class = {2, scene::PathClass::kUnlimited};
  const ref::RenderResult reference = ref::renderReference(scene, reference_settings);
  const std::string n = std::to_string(kEntryPoints);
  std::vector<double> means;
  image::Image sum = reference.mean;
  std::fill(sum.data().begin(), sum.data().end(), 0.0f);
  double one_seed = 0, offset_loss = 0;
  for (int seed = 0; seed < kSeeds; ++seed) {
    const TechniqueRunResult r = runCornell(
        {"output=indirect", "atlas=64", "light_samples=64", "vpl_shadow_map_size=128",
         "entry_points=" + n, "clusters=" + n, "panes_used=" + n, "seed=" + std::to_string(seed)});
    EXPECT_EQ(r.path_class, (scene::PathClass{2, scene::PathClass::kUnlimited}));
    if (seed == 0) {
      one_seed = test::relMseLessNoise(reference, r.image).mean;
      offset_loss = distanceOffsetLoss(scene, test::statisticNamed(r.statistics, "atlas_texels"));
    }
    means.push_back(imageMean(r.image));
    for (std::size_t i = 0; i < sum.data().size(); ++i) sum.data()[i] += r.image.data()[i] / kSeeds;
  }
  const double all_seeds = test::relMseLessNoise(reference, sum).mean;
  const test::MeanEstimate d = test::difference(test::sampleMean(means), imageMean(reference));
  const double expected = imageMean(reference.mean), loss = offset_loss * expected;
  std::printf(
      "relMSE less noise: one seed %.5f, %d seeds %.5f; mean − reference %.5f ± %.5f "
      "(%.1f dof), reference %.5f, offset loss %.4f\n",
      one_seed, kSeeds, all_seeds, d.mean, d.standard_error, d.dof, expected, offset_loss);
  EXPECT_LT(all_seeds, one_seed);
  // The difference's expected value lies in [−loss, 0]: its centre, allowing half the interval.
  EXPECT_TRUE(kFamily.tTest(d.mean, -loss / 2, d.standard_error, d.dof, loss / 2));
}

TEST(LightPathMap, AFixedSeedGivesTheSameImageEveryRun) {
  const std::vector<std::string> set = {"entry_points=64",        "clusters=8",
                                        "panes_used=4",           "atlas=64",
                                        "vpl_shadow_map_size=32", "light_samples=2"};
  std::vector<std::string> other = set;
  other.push_back("seed=1");
  const image::Image a = runCornell(set).image, b = runCornell(set).image;
  const image::Image c = runCornell(other).image;
  EXPECT_TRUE(std::equal(a.data().begin(), a.data().end(), b.data().begin()));
  EXPECT_FALSE(std::equal(a.data().begin(), a.data().end(), c.data().begin()));
}

TEST(LightPathMap, CountsThatDoNotFitAreRefusedWithTheFix) {
  const TechniqueInfo& info = findTechnique("light_path_map");
  auto create = [&](const std::vector<std::string>& set) {
    return info.create(parseParameters(info.parameters, set, "technique 'light_path_map'"));
  };
  auto message = [&](const std::vector<std::string>& set) {
    try {
      create(set);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({"entry_points=0"}).find("entry_points"), std::string::npos);
  EXPECT_NE(message({"entry_points=16", "clusters=32"}).find("give at most one cluster per entry"),
            std::string::npos);
  EXPECT_NE(message({"clusters=8", "panes_used=9"}).find("give at most the cluster count"),
            std::string::npos);
  EXPECT_NO_THROW(create({"entry_points=16", "clusters=16", "panes_used=16"}));
}

// The runner checks the technique's declared need once, before it makes the technique: a caller
// that lends no ray caster is told how to run it.
TEST_F(LightPathMapTest, WithoutARayCasterItSaysHowToRunIt) {
  const TechniqueInfo& info = findTechnique("light_path_map");
  TechniqueRunSettings settings;  // no services lent
  settings.width = settings.height = 16;
  try {
    runTechnique(facingPatches(), info, parseParameters(info.parameters, {}, "light_path_map"),
                 settings);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("gibench render"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace gib::rt
