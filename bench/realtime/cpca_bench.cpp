// Clustered PCA (realtime/prt/cpca.h) at PRT's size: 10 000 transfer vectors of 6 bands × RGB
// (108 values), 16 clusters, 8 basis vectors each (the order of Sloan et al. 2003's settings).
// The vectors are synthetic: each a random blend of two of 32 random prototypes plus 1 % noise,
// so the clusters are real but not exact.
#include "common/splitmix.h"
#include "realtime/prt/cpca.h"

#include <benchmark/benchmark.h>

#include <vector>

namespace {

using namespace gib;

double uniform(std::uint64_t i) {
  return double(splitMix64(23 + i * kGoldenGamma) >> 11) * 0x1p-53;
}

std::vector<float> transferLikeVectors(int count, int dimension) {
  constexpr int kPrototypes = 32;
  std::uint64_t draw = 0;
  std::vector<double> prototypes(std::size_t(kPrototypes * dimension));
  for (double& p : prototypes) p = 2 * uniform(draw++) - 1;
  std::vector<float> out;
  out.reserve(std::size_t(count * dimension));
  for (int i = 0; i < count; ++i) {
    const auto a = std::size_t(uniform(draw++) * kPrototypes);
    const auto b = std::size_t(uniform(draw++) * kPrototypes);
    const double t = uniform(draw++);
    for (int c = 0; c < dimension; ++c)
      out.push_back(float((1 - t) * prototypes[a * std::size_t(dimension) + std::size_t(c)] +
                          t * prototypes[b * std::size_t(dimension) + std::size_t(c)] +
                          0.01 * (2 * uniform(draw++) - 1)));
  }
  return out;
}

void BM_Cpca(benchmark::State& state) {
  const int count = int(state.range(0)), dimension = int(state.range(1));
  const int clusters = int(state.range(2)), pca_vectors = int(state.range(3));
  const std::vector<float> vectors = transferLikeVectors(count, dimension);
  double error = 0;
  for (auto _ : state) {
    const rt::prt::CpcaResult result =
        rt::prt::compressCpca(vectors, dimension, clusters, pca_vectors, 1);
    error = rt::prt::cpcaRelativeError(vectors, result);
    benchmark::DoNotOptimize(result.weights.data());
  }
  state.counters["relative_error"] = error;
  state.SetItemsProcessed(std::int64_t(state.iterations()) * count);
}
BENCHMARK(BM_Cpca)->Args({10000, 108, 16, 8})->Unit(benchmark::kMillisecond);

}  // namespace
