// EXR throughput: every render, reference and error map goes through writeExr and readExr, and a
// suite writes thousands of them.
#include <benchmark/benchmark.h>
#include <stdlib.h>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/exr_io.h"

namespace gib::image {
namespace {

namespace fs = std::filesystem;

constexpr int kSize_px = 1024;

// Write then read one 1024×1024 RGB float32 image; items are pixels, so the rate is pixels/s
// for the round trip.
void BM_ExrWriteRead(benchmark::State& state) {
  // Setup, outside the timed loop: a smooth gradient compresses like a converged render.
  Image image(kSize_px, kSize_px, 3);
  for (int y = 0; y < kSize_px; ++y)
    for (int x = 0; x < kSize_px; ++x)
      for (int c = 0; c < 3; ++c) image.pixel(x, y)[c] = float(x + y * c) / kSize_px;
  std::string pattern = (fs::temp_directory_path() / "gib_exr_bench.XXXXXX").string();
  if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create " + pattern);
  const fs::path dir = pattern;
  const std::vector<Layer> layers = {{"", image}};
  const Metadata metadata = {{"gibench/benchmark", "exr_io"}};

  for (auto _ : state) {
    writeExr(dir / "bench.exr", layers, metadata);
    const ExrFile file = readExr(dir / "bench.exr");
    benchmark::DoNotOptimize(file.layers.front().image.data().data());
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(image.pixelCount()));
  fs::remove_all(dir);
}
// Real time: OpenEXR compresses and decompresses on worker threads, which CPU time of the main
// thread would not count.
BENCHMARK(BM_ExrWriteRead)->Unit(benchmark::kMillisecond)->UseRealTime();

// A file of the size given by the argument (pixels a side), written once, in a directory of its
// own that is removed with it.
class ExrFileFixture {
 public:
  explicit ExrFileFixture(int size_px) {
    std::string pattern = (fs::temp_directory_path() / "gib_exr_bench.XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create " + pattern);
    dir_ = pattern;
    Image image(size_px, size_px, 3);
    for (int y = 0; y < size_px; ++y)
      for (int x = 0; x < size_px; ++x)
        for (int c = 0; c < 3; ++c) image.pixel(x, y)[c] = float(x + y * c) / float(size_px);
    writeExr(path(), {{"", image}, {"variance", image}}, {{"gibench/benchmark", "exr_io"}});
  }
  ~ExrFileFixture() { fs::remove_all(dir_); }
  fs::path path() const { return dir_ / "bench.exr"; }

 private:
  fs::path dir_;
};

// Reading alone (what `gibench compare` and the reference store do), beside the header framing
// check that readExr makes first (BM_ExrHeaderFramingCheck): its share of a read.
void BM_ExrRead(benchmark::State& state) {
  const ExrFileFixture file(int(state.range(0)));
  for (auto _ : state) {
    const ExrFile read = readExr(file.path());
    benchmark::DoNotOptimize(read.layers.front().image.data().data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0) * state.range(0));
}
BENCHMARK(BM_ExrRead)->Arg(32)->Arg(1024)->Unit(benchmark::kMicrosecond)->UseRealTime();

void BM_ExrHeaderFramingCheck(benchmark::State& state) {
  const ExrFileFixture file(int(state.range(0)));
  for (auto _ : state) checkExrHeaderFraming(file.path());
}
BENCHMARK(BM_ExrHeaderFramingCheck)->Arg(32)->Arg(1024)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace gib::image
