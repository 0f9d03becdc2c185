// The report viewer's data: every job of a run writes its image and FLIP map as half floats in
// base64 (image/viewer_data.h), so at the nightly suite's 512² this is on every job's path, beside
// the EXR and PNG writes.
#include <benchmark/benchmark.h>

#include <cstdint>

#include "image/viewer_data.h"

namespace gib::image {
namespace {

// One 512×512 RGB image and a one-channel map, as a technique job writes them; items are pixels.
void BM_ViewerDataScript512(benchmark::State& state) {
  constexpr int kSize = 512;
  Image image(kSize, kSize, 3);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (int c = 0; c < 3; ++c) image.pixel(x, y)[c] = float(x + y * c) / kSize;
  const Image flip(kSize, kSize, 1, 0.25f);
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string script =
        viewerDataScript("jobs/a/viewer.js", {{"image", &image}, {"flip", &flip}});
    bytes = script.size();
    benchmark::DoNotOptimize(script.data());
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(image.pixelCount()));
  state.counters["script_bytes"] = double(bytes);
}
BENCHMARK(BM_ViewerDataScript512)->Unit(benchmark::kMillisecond);

// The thumbnail of a 512² image: a 4 × 4 box filter to 128².
void BM_Thumbnail512(benchmark::State& state) {
  Image image(512, 512, 3, 0.5f);
  for (auto _ : state) benchmark::DoNotOptimize(downsampleToWidth(image, 128).data().data());
  state.SetItemsProcessed(state.iterations() * std::int64_t(image.pixelCount()));
}
BENCHMARK(BM_Thumbnail512)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gib::image
