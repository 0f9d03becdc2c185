// Progressive rendering of the reference image: passes of samples over tiles (TBB), per-pixel
// mean and variance from running sums, snapshots at 1, 2, 4, … samples per pixel.
#pragma once

#include "image/image.h"
#include "reference/path_tracer.h"
#include "scene/scene.h"

#include <cstdint>
#include <functional>

namespace gib::ref {

struct RenderSettings {
  int width = 512;
  int height = 512;
  std::uint32_t spp = 64;
  std::uint64_t seed = 0;
  PathClass path_class;
  int threads = 0;        // 0: all cores. The image does not depend on it.
  bool progress = false;  // draw a progress bar on a terminal
};

struct RenderResult {
  image::Image mean;
  // Variance of the per-pixel mean (the sample variance divided by spp), so that
  // mean ± 3·sqrt(variance) is a 3-standard-error interval. Empty when spp < 2.
  image::Image variance;
  image::Image direct;    // mean of the paths with at most one bounce
  image::Image indirect;  // mean of the paths with two bounces or more
  std::uint32_t spp = 0;
  std::uint64_t rays = 0;
  double seconds = 0;
  double raysPerSecond() const { return seconds > 0 ? double(rays) / seconds : 0; }
};

// Called after the passes that end at 1, 2, 4, … spp (and at the final spp) with the mean so far.
using CheckpointCallback = std::function<void(std::uint32_t spp, const image::Image& mean)>;

// Throws gib::InputError for impossible settings (zero size or spp, negative bounces, min > max).
void validateRenderSettings(const RenderSettings& settings);

RenderResult renderReference(const scene::Scene& scene, const RenderSettings& settings,
                             const CheckpointCallback& on_checkpoint = {});

// The sample-count boundaries of the passes: 1, 2, 4, …, up to and including spp.
std::vector<std::uint32_t> passBoundaries(std::uint32_t spp);

}  // namespace gib::ref
