// The reference on mirrors and glass (docs/rendering.md, "Caustics: light tracing"), side by side
// in one run: rays per second on the spheres box with and without light paths beside bare Embree
// on the same box, and what the light paths buy: each image's efficiency 1/(MSE · seconds) against
// a long render, for the whole image and for its caustics alone (the class L S+ D E), and the time
// to relMSE 1e-3 (fitted over the checkpoints, extrapolated).
#include "reference/embree_scene.h"
#include "reference/progressive_renderer.h"
#include "reference/rng.h"
#include "reference/sampling.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"
#include "support/reference_measures.h"

#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <vector>

namespace {

using namespace gib;

scene::Scene spheresBox() {
  return scene::loadScene("cornell", {"spheres=mirror_glass"});
}

// state.range(0): light paths (ref::LightPaths).
void BM_ReferenceSpheres256(benchmark::State& state) {
  const scene::Scene scene = spheresBox();
  ref::RenderSettings settings;
  settings.width = settings.height = 256;
  settings.spp = 16;
  settings.light_paths = ref::LightPaths(state.range(0));
  state.SetLabel(std::string("light paths ") + ref::lightPathsName(settings.light_paths));
  std::uint64_t rays = 0;
  for (auto _ : state) {
    const ref::RenderResult r = ref::renderReference(scene, settings);
    rays += r.rays;
    benchmark::DoNotOptimize(r.mean.data().data());
  }
  state.counters["rays/s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
  state.counters["samples/s"] = benchmark::Counter(
      double(state.iterations()) * 256 * 256 * settings.spp, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ReferenceSpheres256)
    ->Arg(int(ref::LightPaths::kAuto))
    ->Arg(int(ref::LightPaths::kOff))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Bare rtcIntersect1 on the spheres box: camera rays at 256×256 and as many cosine rays from
// random triangles (the spheres' 2 × 16,000 triangles dominate the count, so most leave a sphere).
void BM_BareEmbreeIntersectSpheres(benchmark::State& state) {
  const scene::Scene scene = spheresBox();
  const ref::EmbreeScene embree(scene);
  std::vector<scene::Ray> rays;
  const scene::CameraFrame camera = scene::makeCameraFrame(scene.camera, 256, 256);
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x)
      rays.push_back(
          {camera.origin, scene::cameraRayDirection(camera, 256, 256, x + 0.5f, y + 0.5f)});
  std::vector<glm::vec3> points;
  for (const scene::Mesh& mesh : scene.meshes)
    for (const glm::uvec3& t : mesh.triangles)
      points.push_back((mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0f);
  for (std::uint32_t i = 0; i < 256u * 256u; ++i) {
    ref::SampleStream random(7, i, 0);
    const glm::vec3 d = ref::Frame(glm::vec3(0, 1, 0))
                            .toWorld(ref::sampleUniformHemisphere({random.next(), random.next()}));
    rays.push_back({points[i % points.size()] + 0.5f * d, random.next() < 0.5f ? d : -d});
  }
  bench::measureBareEmbree(state, embree, rays);
}
BENCHMARK(BM_BareEmbreeIntersectSpheres)->Unit(benchmark::kMillisecond)->UseRealTime();

constexpr int kSize = 64;
constexpr std::uint32_t kSpp = 64;
constexpr std::uint32_t kTruthSpp = 4096;

// The long render of the spheres box (all paths, or the caustics' class), with light paths and
// another seed, made once per process.
const image::Image& truthOf(const std::string& paths) {
  static std::map<std::string, image::Image> truths;
  auto it = truths.find(paths);
  if (it == truths.end()) {
    ref::RenderSettings settings;
    settings.width = settings.height = kSize;
    settings.spp = kTruthSpp;
    settings.seed = 1000;
    settings.path_class.expression = paths;
    it = truths.emplace(paths, ref::renderReference(spheresBox(), settings).mean).first;
  }
  return it->second;
}

// state.range(0): light paths; state.range(1): 1 for the caustics alone (L S+ D E).
void BM_SpheresEfficiency(benchmark::State& state) {
  const std::string paths = state.range(1) ? "LS+DE" : "";
  const image::Image& truth = truthOf(paths);
  const scene::Scene scene = spheresBox();
  ref::RenderSettings settings;
  settings.width = settings.height = kSize;
  settings.spp = kSpp;
  settings.light_paths = ref::LightPaths(state.range(0));
  settings.path_class.expression = paths;
  bench::measureEfficiency(state, scene, settings, truth);
  state.SetLabel(std::string(state.range(1) ? "LS+DE" : "all paths") + ", light paths " +
                 ref::lightPathsName(settings.light_paths));
}
BENCHMARK(BM_SpheresEfficiency)
    ->ArgsProduct({{int(ref::LightPaths::kAuto), int(ref::LightPaths::kOff)}, {0, 1}})
    ->Iterations(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
