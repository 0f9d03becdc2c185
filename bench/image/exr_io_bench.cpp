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

// A directory of its own under the system's temporary directory, removed with this.
class BenchDirectory {
 public:
  BenchDirectory() {
    std::string pattern = (fs::temp_directory_path() / "gib_exr_bench.XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create " + pattern);
    path_ = pattern;
  }
  ~BenchDirectory() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// A smooth gradient, which compresses like a converged render.
Image gradient(int size_px) {
  Image image(size_px, size_px, 3);
  for (int y = 0; y < size_px; ++y)
    for (int x = 0; x < size_px; ++x)
      for (int c = 0; c < 3; ++c) image.pixel(x, y)[c] = float(x + y * c) / float(size_px);
  return image;
}

// Write then read one 1024×1024 RGB float32 image; items are pixels, so the rate is pixels/s
// for the round trip.
void BM_ExrWriteRead(benchmark::State& state) {
  const Image image = gradient(kSize_px);
  const BenchDirectory dir;
  const std::vector<Layer> layers = {{"", image}};
  const Metadata metadata = {{"gibench/benchmark", "exr_io"}};

  for (auto _ : state) {
    writeExr(dir.path() / "bench.exr", layers, metadata);
    const ExrFile file = readExr(dir.path() / "bench.exr");
    benchmark::DoNotOptimize(file.layers.front().image.data().data());
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(image.pixelCount()));
}
// Real time: OpenEXR compresses and decompresses on worker threads, which CPU time of the main
// thread would not count.
BENCHMARK(BM_ExrWriteRead)->Unit(benchmark::kMillisecond)->UseRealTime();

// A file of mean and variance, `size_px` a side, written once.
class ExrFileFixture {
 public:
  explicit ExrFileFixture(int size_px) {
    const Image image = gradient(size_px);
    writeExr(path(), {{"", image}, {"variance", image}}, {{"gibench/benchmark", "exr_io"}});
  }
  fs::path path() const { return dir_.path() / "bench.exr"; }

 private:
  BenchDirectory dir_;
};

// Reading alone (what `gibench compare` and the reference store do), beside the header framing
// check that readExr makes first (BM_ExrHeaderCheck): its share of a read.
void BM_ExrRead(benchmark::State& state) {
  const ExrFileFixture file(int(state.range(0)));
  for (auto _ : state) {
    const ExrFile read = readExr(file.path());
    benchmark::DoNotOptimize(read.layers.front().image.data().data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0) * state.range(0));
}
BENCHMARK(BM_ExrRead)->Arg(32)->Arg(1024)->Unit(benchmark::kMicrosecond)->UseRealTime();

void BM_ExrHeaderCheck(benchmark::State& state) {
  const ExrFileFixture file(int(state.range(0)));
  for (auto _ : state) checkExrHeader(file.path());
}
BENCHMARK(BM_ExrHeaderCheck)->Arg(32)->Arg(1024)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace gib::image
