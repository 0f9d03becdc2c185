// The reference store's hot paths in a run: a hit (reading entry.json and the EXR of mean and
// variance) at 128² and 512², the key of a spec (hashing the canonical scene), and taking and
// releasing a key's cross-process lock (what every render pays to keep renders to one per key).
#include "reference/reference_store.h"
#include "reference/reference_store_lock.h"
#include "scene/builtin_scenes.h"
#include "support/temporary_directory.h"

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

namespace {

using namespace gib;

// obtain() of a stored entry: what every job of a run pays once its reference exists.
void BM_ObtainHit(benchmark::State& state) {
  const bench::TemporaryDirectory temporary("gib_store_bench");
  ref::ReferenceStore store(temporary.path());
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

// mkdir, the owner file, the heartbeat thread's start and stop, and the removal.
void BM_StoreKeyLockCycle(benchmark::State& state) {
  const bench::TemporaryDirectory temporary("gib_lock_bench");
  const std::filesystem::path lock_dir = temporary.path() / "locks" / "0123abcd";
  for (auto _ : state) {
    std::unique_ptr<ref::StoreKeyLock> lock = ref::StoreKeyLock::tryAcquire(lock_dir);
    if (!lock) state.SkipWithError("the lock was not free");
    lock.reset();
  }
}
BENCHMARK(BM_StoreKeyLockCycle)->Unit(benchmark::kMicrosecond)->UseRealTime();

void BM_ReferenceKeyCornell(benchmark::State& state) {
  const scene::Scene cornell = scene::loadScene("cornell");
  ref::ReferenceSpec spec;
  spec.scene = "cornell";
  for (auto _ : state) benchmark::DoNotOptimize(ref::referenceKey(cornell, spec));
}
BENCHMARK(BM_ReferenceKeyCornell)->Unit(benchmark::kMicrosecond);

}  // namespace
