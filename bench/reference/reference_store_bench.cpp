// The reference store's hot paths in a run: a hit (reading entry.json and the EXR of mean and
// variance) at 128² and 512², and the key of a spec (hashing the canonical scene).
#include "reference/reference_store.h"
#include "scene/builtin_scenes.h"

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace {

using namespace gib;

// A store in a fresh temporary directory, removed at the end.
class TemporaryStore {
 public:
  TemporaryStore() {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "gib_store_bench.XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create " + pattern);
    root_ = pattern;
  }
  ~TemporaryStore() { std::filesystem::remove_all(root_); }
  const std::filesystem::path& root() const { return root_; }

 private:
  std::filesystem::path root_;
};

// obtain() of a stored entry: what every job of a run pays once its reference exists.
void BM_ObtainHit(benchmark::State& state) {
  TemporaryStore temporary;
  ref::ReferenceStore store(temporary.root());
  const scene::Scene cornell = scene::loadScene("cornell");
  ref::ReferenceSpec spec;
  spec.scene = "cornell";
  spec.width = spec.height = int(state.range(0));
  spec.spp = 2;  // the render is setup, not measured; two samples give the variance layer
  store.obtain(cornell, spec);
  for (auto _ : state) {
    ref::StoredReference hit = store.obtain(cornell, spec);
    if (!hit.hit) state.SkipWithError("the second obtain() rendered");
    benchmark::DoNotOptimize(hit.mean.data().data());
  }
  state.counters["pixels/s"] = benchmark::Counter(
      double(state.iterations()) * double(spec.width * spec.height), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ObtainHit)->Arg(128)->Arg(512)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ReferenceKeyCornell(benchmark::State& state) {
  const scene::Scene cornell = scene::loadScene("cornell");
  ref::ReferenceSpec spec;
  spec.scene = "cornell";
  for (auto _ : state) benchmark::DoNotOptimize(ref::referenceKey(cornell, spec));
}
BENCHMARK(BM_ReferenceKeyCornell)->Unit(benchmark::kMicrosecond);

}  // namespace
