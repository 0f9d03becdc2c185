// The frame benchmark every real-time technique shares: one frame per benchmark iteration on the
// machine's GL device, finished with glFinish and timed by wall clock, after warm-up frames; the
// pass profiler's medians come out as counters "<pass>_ms" in its reported clock (CPU around
// glFinish on llvmpipe or for a technique timed on the CPU, GPU timestamps on a GPU), the
// technique's statistics are counters of their own names, and the label names the renderer.
#pragma once

#include "realtime/technique.h"

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace gib::rt {

// The image is `size` pixels square, or width × size with `width` given; `services` is what the
// harness would lend (TechniqueServices: a ray caster for CPU preprocessing); `scene_set` the
// scene's parameters (key=value).
void benchmarkTechniqueFrames(benchmark::State& state, const std::string& technique,
                              const std::vector<std::string>& set, const std::string& scene,
                              int size, int width = 0, const TechniqueServices& services = {},
                              const std::vector<std::string>& scene_set = {});

// The same for one iteration of an iterative technique (Technique::step) per benchmark iteration,
// after `warmup_iterations`; counters "<pass>_ms" are the medians of the iteration's passes.
void benchmarkTechniqueIterations(benchmark::State& state, const std::string& technique,
                                  const std::vector<std::string>& set, const std::string& scene,
                                  int warmup_iterations,
                                  const std::vector<std::string>& scene_set = {});

}  // namespace gib::rt
