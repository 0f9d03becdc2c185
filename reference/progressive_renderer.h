// Progressive rendering of the reference image: passes of samples over tiles (TBB), per-pixel
// mean and, from independently scrambled replicas, the variance of that mean; snapshots at 1, 2,
// 4, … samples per pixel.
#pragma once

#include "image/image.h"
#include "reference/path_tracer.h"
#include "scene/obscurance.h"
#include "scene/scene.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace gib::ref {

// Where a pixel's camera rays go (docs/rendering.md, "Pixel sampling").
enum class PixelSampling {
  // A uniform point in the pixel for each sample: the pixel's area integral under a box filter,
  // anti-aliased. What another renderer (Cycles) computes; the reference's own checks use it.
  kArea,
  // Every sample through the pixel's centre, the rasteriser's sample position: one primary hit
  // per pixel (the G-buffer's), and all the samples spent on its lighting. What a real-time
  // technique is measured against, so its error is its lighting's, not anti-aliasing's.
  kCenter,
};

// Whether light paths join the camera paths (docs/rendering.md, "Caustics: light tracing").
enum class LightPaths {
  // When the scene has mirrors or glass and no medium (LightTracer::applies): the caustics'
  // paths, L S (D|S)* D E, are traced from the lights. Unbiased either way for an area light;
  // the only way to reach those paths from a spot or directional light.
  kAuto,
  // Camera paths only: what a plain path tracer computes, kept to measure what the light paths
  // buy. Caustics of delta lights are missing.
  kOff,
};

struct RenderSettings {
  int width = 512;
  int height = 512;
  std::uint32_t spp = 64;
  std::uint64_t seed = 0;
  // Independently scrambled batches the samples are split into (reference/path_sampler.h); it
  // must divide spp. 0: automatic (defaultReplicas).
  std::uint32_t replicas = 0;
  SamplerKind sampler = SamplerKind::kSobol;
  PixelSampling pixel_sampling = PixelSampling::kArea;
  PathClass path_class;
  LightPaths light_paths = LightPaths::kAuto;
  // When set, the image is not radiance but this obscurance W(x) at each camera ray's first hit
  // (0 where the ray hits nothing), one ray of reference/obscurance_estimator.h per sample about
  // the geometric normal turned towards the camera: the quantity an obscurances technique's image
  // holds (docs/rendering.md, "Obscurances"). Replicas, variance, checkpoints and determinism are
  // as for radiance; light paths are not traced and the path class is ignored; `direct` holds
  // the mean and `indirect` zero.
  std::optional<scene::ObscuranceDefinition> obscurance;
  // False: light from the environment (a constant sky or a map) reaches every point unblocked,
  // v(x, ω) = 1 for it alone (book §4.2.1-4.2.2's assumption), so that an environment-mapping
  // technique's convolution error can be told from its missing shadows (PathTracer).
  bool environment_occlusion = true;
  int threads = 0;        // 0: all cores. The image does not depend on it.
  bool progress = false;  // draw a progress bar on a terminal
};

struct RenderResult {
  image::Image mean;
  // Variance of the per-pixel mean, estimated from the spread of the replicas' means (the samples
  // of one replica are correlated, so the per-sample variance would not do), with
  // `variance_dof` = replicas − 1 degrees of freedom: (mean − truth)/sqrt(variance) follows
  // Student's t with that many. Empty with one replica.
  image::Image variance;
  std::uint32_t replicas = 1;
  std::uint32_t variance_dof = 0;
  image::Image direct;    // mean of the paths with at most one bounce
  image::Image indirect;  // mean of the paths with two bounces or more
  std::uint32_t spp = 0;
  bool light_paths = false;  // whether light paths were traced (LightPaths::kAuto applied)
  std::uint64_t rays = 0;
  double seconds = 0;
  double raysPerSecond() const { return seconds > 0 ? double(rays) / seconds : 0; }
};

// Called after the passes that end at 1, 2, 4, … spp (and at the final spp) with the mean so far.
using CheckpointCallback = std::function<void(std::uint32_t spp, const image::Image& mean)>;

// Throws gib::InputError for impossible settings (zero size or spp, negative bounces, min > max,
// a replica count that does not divide spp).
void validateRenderSettings(const RenderSettings& settings);

// The replicas a render of `spp` samples per pixel uses when none are asked for: the largest
// divisor of spp up to kDefaultMaxReplicas, or spp itself when that is 1 and spp > 1 (then
// samples are independent and the variance is the classic one). More replicas estimate the
// variance better (more degrees of freedom), fewer keep more of the low-discrepancy convergence
// (on the light's edges of the Cornell box the MSE grows as √replicas; over the empty box at
// 256×192 and 1024 spp, 4 replicas have 0.68 times the MSE of 8) and make each replica's mean
// closer to normal, which the t statistic assumes (docs/rendering.md, "Error bars").
inline constexpr std::uint32_t kDefaultMaxReplicas = 4;
std::uint32_t defaultReplicas(std::uint32_t spp);
// settings.replicas, or the default when it is 0.
std::uint32_t replicasOf(const RenderSettings& settings);

// "sobol" or "independent", as the command line and the metadata name them.
const char* samplerName(SamplerKind kind);
// Throws gib::InputError naming the choices for any other name.
SamplerKind parseSamplerName(const std::string& name);
// "auto" or "off", as the command line and the metadata name them.
const char* lightPathsName(LightPaths mode);
// Throws gib::InputError naming the choices for any other name.
LightPaths parseLightPaths(const std::string& name);
// Whether a render of `scene` with `mode` traces light paths.
bool tracesLightPaths(const scene::Scene& scene, LightPaths mode);
// Whether a render of `scene` with `settings` does: never for an obscurance.
bool tracesLightPaths(const scene::Scene& scene, const RenderSettings& settings);
// "area" or "center", as the command line, suites, metadata and results name them.
const char* pixelSamplingName(PixelSampling sampling);
// Throws gib::InputError naming the choices for any other name.
PixelSampling parsePixelSampling(const std::string& name);

RenderResult renderReference(const scene::Scene& scene, const RenderSettings& settings,
                             const CheckpointCallback& on_checkpoint = {});

// The sample-count boundaries of the passes: 1, 2, 4, …, up to and including spp.
std::vector<std::uint32_t> passBoundaries(std::uint32_t spp);

}  // namespace gib::ref
