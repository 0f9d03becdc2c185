// What the reference benchmarks measure alike: bare Embree's closest hits over a ray set (the
// floor a path tracer's rays per second are compared with), and a render's efficiency against a
// long render of the same scene (docs/rendering.md, "Sampling").
#pragma once

#include "image/image.h"
#include "reference/embree_scene.h"
#include "reference/progressive_renderer.h"
#include "scene/ray_caster.h"

#include <benchmark/benchmark.h>

#include <span>

namespace gib::bench {

// Traces every ray with rtcIntersect1 on all cores, once per benchmark iteration, and sets the
// counter rays/s.
void measureBareEmbree(benchmark::State& state, const ref::EmbreeScene& embree,
                       std::span<const scene::Ray> rays);

// Renders `scene` with `settings` once per iteration (the seed advanced each time, for
// independent noise) and sets the counters mse and efficiency 1/(MSE · seconds) against `truth`,
// and, from the relMSE of the checkpoints from 8 spp on (relMSE = a·spp^slope), relmse_slope and
// s_to_relmse_1e-3, the time at which the fit reaches 1e-3.
void measureEfficiency(benchmark::State& state, const scene::Scene& scene,
                       ref::RenderSettings settings, const image::Image& truth);

}  // namespace gib::bench
