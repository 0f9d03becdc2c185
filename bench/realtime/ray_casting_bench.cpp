// The hot paths of GPU ray casting (book Ch. 5; realtime/ray_casting/README.md) on the GL device:
// one cast of a fixed batch of rays through each structure (brute_force, loose_kd_tree, bvh) and
// through the ray engine with and without its tile cones, primary and diffuse rays on the chamber
// at detail 1 (3 384 triangles), 128 × 128 rays; and the per-triangle IVM set's construction.
// `gibench raycast-bench` is the full table against Embree; this is what a change to a cast is
// measured with.
#include "realtime/gl/context.h"
#include "realtime/ray_casting/ray_cast_pass.h"
#include "realtime/ray_casting/ray_engine.h"
#include "realtime/ray_casting/ray_sets.h"
#include "realtime/ray_casting/ray_structures.h"
#include "reference/embree_scene.h"
#include "scene/builtin_scenes.h"

#include <benchmark/benchmark.h>

#include <memory>

namespace gib::rt {
namespace {

constexpr int kSide = 128;

gl::Context& context() {
  static std::unique_ptr<gl::Context> context = gl::Context::create();
  return *context;
}

struct Fixture {
  scene::Scene scene = scene::loadScene("chamber", {"detail=1"});
  IvmTriangleSet set = buildIvmTriangles(scene);
  std::vector<CastRay> rays[2];  // primary, diffuse

  Fixture() {
    const std::unique_ptr<scene::RayCaster> caster = ref::embreeRayCasterFactory()(scene);
    int k = 0;
    for (RayKind kind : {RayKind::kPrimary, RayKind::kDiffuse})
      rays[k++] = castRaysOf(set, makeRaySet(scene, kind, kSide, kSide, 1, *caster));
  }
};

const Fixture& fixture() {
  context();
  static const Fixture f;
  return f;
}

// state.range(0): the structure's index in gpuRayStructureNames(); range(1): 0 primary, 1 diffuse.
void BM_CastStructure(benchmark::State& state) {
  const Fixture& f = fixture();
  const std::string& name = gpuRayStructureNames().at(std::size_t(state.range(0)));
  const std::unique_ptr<GpuRayStructure> structure = makeGpuRayStructure(name, f.set);
  RayCastPass pass(*structure);
  const std::vector<CastRay>& rays = f.rays[state.range(1)];
  pass.setRays(rays);
  // llvmpipe compiles a program at its first dispatch: one untimed cast first.
  pass.cast();
  glFinish();
  for (auto _ : state) {
    pass.cast();
    glFinish();
  }
  state.SetLabel(name + (state.range(1) == 0 ? " primary" : " diffuse"));
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(rays.size()));
}
BENCHMARK(BM_CastStructure)
    ->ArgsProduct({{0, 1, 2}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// state.range(0): 1 with cones (§5.3), 0 without (§5.2); range(1) as above.
void BM_CastRayEngine(benchmark::State& state) {
  const Fixture& f = fixture();
  RayEngine engine(f.set, state.range(0) == 1);
  engine.setRays(f.rays[state.range(1)], kSide);
  engine.cast();  // untimed: the programs' compilation at their first use
  glFinish();
  for (auto _ : state) {
    engine.cast();
    glFinish();
  }
  state.counters["kept_pairs"] = engine.keptPairFraction();
  state.SetLabel(std::string(engine.name()) + (state.range(1) == 0 ? " primary" : " diffuse"));
  state.SetItemsProcessed(std::int64_t(state.iterations()) *
                          std::int64_t(f.rays[state.range(1)].size()));
}
BENCHMARK(BM_CastRayEngine)
    ->ArgsProduct({{0, 1}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The per-triangle IVMs and apexes (and the origin's lattice search) of the chamber at detail 5.
void BM_BuildIvmTriangles(benchmark::State& state) {
  const scene::Scene scene = scene::loadScene("chamber", {"detail=5"});
  for (auto _ : state) benchmark::DoNotOptimize(buildIvmTriangles(scene).triangles.data());
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(scene.triangleCount()));
}
BENCHMARK(BM_BuildIvmTriangles)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gib::rt
