// The projection of a latitude–longitude environment map on spherical harmonics (realtime/sh/
// sh_projection.h): a 256×128 map of random texels on 6 bands (book Fig. 8.4's order), turned.
#include "common/splitmix.h"
#include "realtime/sh/sh_projection.h"
#include "scene/environment_map.h"

#include <benchmark/benchmark.h>

#include <vector>

namespace {

using namespace gib;

void BM_ShProjectLatLong(benchmark::State& state) {
  const int height = 128, width = 256, bands = int(state.range(0));
  std::vector<float> texels(std::size_t(3 * width * height));
  for (std::size_t i = 0; i < texels.size(); ++i)
    texels[i] = float(double(splitMix64(17 + i * kGoldenGamma) >> 11) * 0x1p-53);
  scene::EnvironmentMap map = scene::makeEnvironmentMap(width, height, std::move(texels), "bench");
  map.rotation_deg = 30.0f;
  for (auto _ : state) {
    const std::vector<glm::vec3> c = rt::sh::projectLatLong(map, bands);
    benchmark::DoNotOptimize(c.data());
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * width * height);
}
BENCHMARK(BM_ShProjectLatLong)->Arg(6)->Unit(benchmark::kMicrosecond);

}  // namespace
