#include "support/reference_measures.h"

#include "metrics/convergence_fit.h"
#include "metrics/image_metrics.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <vector>

namespace gib::bench {

void measureBareEmbree(benchmark::State& state, const ref::EmbreeScene& embree,
                       std::span<const scene::Ray> rays) {
  for (auto _ : state) {
    std::atomic<std::uint32_t> hits{0};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 4096), [&](auto range) {
      std::uint32_t local = 0;
      for (std::size_t i = range.begin(); i != range.end(); ++i)
        local += embree.intersect(rays[i].origin, rays[i].direction).valid();
      hits += local;
    });
    benchmark::DoNotOptimize(hits.load());
  }
  state.counters["rays/s"] = benchmark::Counter(double(state.iterations()) * double(rays.size()),
                                                benchmark::Counter::kIsRate);
}

void measureEfficiency(benchmark::State& state, const scene::Scene& scene,
                       ref::RenderSettings settings, const image::Image& truth) {
  double mse = 0, seconds = 0;
  std::vector<double> log_spp, log_relmse;
  for (auto _ : state) {
    log_spp.clear();
    log_relmse.clear();
    const auto start = std::chrono::steady_clock::now();
    const ref::RenderResult r =
        ref::renderReference(scene, settings, [&](std::uint32_t spp, const image::Image& mean) {
          if (spp < 8) return;  // before the asymptotic rate
          log_spp.push_back(std::log(double(spp)));
          log_relmse.push_back(std::log(metrics::computeRelMse(truth, mean).value));
        });
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    mse += metrics::computeMse(truth, r.mean).value;
    settings.seed += 1;  // independent noise in each iteration
  }
  const double n = double(state.iterations());
  mse /= n;
  seconds /= n;
  state.counters["mse"] = mse;
  state.counters["efficiency"] = 1.0 / (mse * seconds);
  // relMSE = a·spp^slope: the spp, and so the time, at which it reaches 1e-3.
  const metrics::LinearFit fit = metrics::fitLine(log_spp, log_relmse);
  const double spp_needed = std::exp((std::log(1e-3) - fit.intercept) / fit.slope);
  state.counters["relmse_slope"] = fit.slope;
  state.counters["s_to_relmse_1e-3"] = spp_needed * seconds / double(settings.spp);
}

}  // namespace gib::bench
