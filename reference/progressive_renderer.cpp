#include "reference/progressive_renderer.h"

#include "common/input_error.h"
#include "common/parallel_for.h"
#include "common/progress.h"
#include "reference/light_tracer.h"
#include "reference/obscurance_estimator.h"
#include "scene/camera.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <glm/geometric.hpp>

#include <fmt/format.h>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

namespace gib::ref {

namespace {

constexpr int kTileSize = 16;
// Camera rays of one pixel traced together (at most): enough for Embree's packets of 8 or 16 to
// fill, few enough that the batch's samplers and rays stay in the first-level cache.
constexpr std::uint32_t kCameraBatch = 64;
// Light paths are traced in blocks of this many samples of every pixel slot; each tile's splats
// of a block are kept, then added in tile order, so the sums do not depend on the threads, and
// the splats held at once stay bounded.
constexpr std::uint32_t kLightPathBlock = 8;
// The light paths' sampler seed, apart from the camera paths' (a salt mixed into the seed).
constexpr std::uint64_t kLightPathSeedSalt = 0x6c69676874706174ull;  // "lightpat"

// Running sums per pixel, in double so that millions of samples do not lose precision. The
// replicas' sums (for the variance) live in a separate array of replicas × 3 per pixel.
struct PixelSums {
  double sum[3] = {0, 0, 0};
  double direct[3] = {0, 0, 0};
};

struct Tile {
  int x0, y0, x1, y1;
};

std::vector<Tile> makeTiles(int width, int height) {
  std::vector<Tile> tiles;
  for (int y = 0; y < height; y += kTileSize)
    for (int x = 0; x < width; x += kTileSize)
      tiles.push_back({x, y, std::min(x + kTileSize, width), std::min(y + kTileSize, height)});
  return tiles;
}

// One pixel's camera rays for a run of its samples, traced together: rays through one pixel are
// coherent, and Embree traces a batch as packets for a fraction of the cost of single rays. Each
// hit is bit-identical to the single ray's (tested), so the image does not depend on the
// batching. One per task, reused from pixel to pixel.
class CameraBatch {
 public:
  CameraBatch() {
    samplers_.reserve(kCameraBatch);
    rays_.reserve(kCameraBatch);
    hits_.reserve(kCameraBatch);
  }

  // Samples [first, end) of pixel (x, y), at most kCameraBatch of them.
  void trace(const PathTracer& tracer, const scene::CameraFrame& camera,
             const RenderSettings& settings, std::uint32_t replicas, int x, int y,
             std::uint32_t first, std::uint32_t end) {
    const auto pixel = std::uint32_t(y * settings.width + x);
    samplers_.clear();
    rays_.clear();
    const bool centre = settings.pixel_sampling == PixelSampling::kCenter;
    for (std::uint32_t s = first; s < end; ++s) {
      samplers_.emplace_back(settings.seed, pixel, s, replicas, settings.sampler);
      // Box filter: a uniform point in the pixel. At the centre, the sample's first two
      // dimensions go unused, so the lighting's dimensions are those of the box filter's samples.
      const glm::vec2 position =
          glm::vec2(x, y) + (centre ? glm::vec2(0.5f) : samplers_.back().pixelPosition());
      // A thin lens draws its point for every sample, at the pixel's centre too: depth of field
      // is the lens's spread, not anti-aliasing.
      const glm::vec2 lens =
          camera.lens_radius > 0 ? samplers_.back().lensPosition() : glm::vec2(0.0f);
      const scene::CameraRay ray =
          scene::cameraRay(camera, settings.width, settings.height, position.x, position.y, lens);
      rays_.push_back({ray.origin, ray.direction});
    }
    hits_.resize(rays_.size());
    if (centre && camera.lens_radius == 0) {
      // One ray, the same for every sample: traced once (a single ray's hit is bit-identical to
      // a batch's, tested), and its hit shared.
      hits_.front() = tracer.embree().intersect(rays_.front().origin, rays_.front().direction);
      std::fill(hits_.begin() + 1, hits_.end(), hits_.front());
    } else {
      tracer.embree().intersect(rays_, hits_, /*coherent=*/true);
    }
  }

  // The path of the batch's i-th sample, from its camera ray's hit on.
  RadianceSample radiance(const PathTracer& tracer, std::size_t i) {
    return tracer.radiance(rays_[i].origin, rays_[i].direction, samplers_[i], &hits_[i]);
  }

  // The batch's i-th sample of the obscurance at its camera ray's hit (0 for a miss): one ray
  // about the geometric normal turned towards the camera, from the first vertex's direction
  // dimensions (the ones a path's first bounce would use). Counted as a bounce-less sample:
  // all of it is `direct`.
  RadianceSample obscurance(const ObscuranceEstimator& estimator, std::size_t i) {
    RadianceSample out;
    out.rays = 1;
    const Hit& hit = hits_[i];
    if (!hit.valid()) return out;
    const TriangleTable& triangles = estimator.triangles();
    const TriangleRecord& triangle = triangles[triangles.globalIndex(hit.mesh, hit.triangle)];
    const glm::vec3& direction = rays_[i].direction;
    const glm::vec3 normal =
        glm::dot(triangle.normal, direction) <= 0 ? triangle.normal : -triangle.normal;
    PathSampler& sampler = samplers_[i];
    sampler.startVertex(0);
    out.total = estimator.sample(rays_[i].origin + hit.t * direction, normal,
                                 sampler.get2D(VertexDimension::kDirection));
    out.direct = out.total;
    ++out.rays;
    return out;
  }

 private:
  std::vector<PathSampler> samplers_;
  std::vector<scene::Ray> rays_;
  std::vector<Hit> hits_;
};

image::Image meanImage(const std::vector<PixelSums>& sums, int width, int height, std::uint32_t n) {
  image::Image mean(width, height);
  for (std::size_t i = 0; i < sums.size(); ++i)
    for (int c = 0; c < 3; ++c) mean.data()[3 * i + c] = float(sums[i].sum[c] / n);
  return mean;
}

}  // namespace

void validateRenderSettings(const RenderSettings& s) {
  if (s.width <= 0 || s.height <= 0)
    throw InputError(fmt::format("image size {}x{} is not positive; give --width and --height > 0",
                                 s.width, s.height));
  if (s.spp == 0) throw InputError("--spp 0 renders nothing; give at least 1 sample per pixel");
  if (s.path_class.min_bounces < 0 || s.path_class.max_bounces < 0)
    throw InputError("bounce limits must be >= 0");
  if (s.path_class.min_bounces > s.path_class.max_bounces)
    throw InputError(fmt::format("--min-bounces {} exceeds --max-bounces {}; no path is left",
                                 s.path_class.min_bounces, s.path_class.max_bounces));
  if (s.threads < 0) throw InputError("--threads must be >= 0 (0 uses every core)");
  if (s.obscurance) scene::validateObscuranceDistanceFraction(s.obscurance->d_max_fraction);
  if (s.replicas > 0 && s.spp % s.replicas != 0)
    throw InputError(fmt::format(
        "--replicas {} does not divide --spp {}; give a divisor of the sample count (or 0 for "
        "the default, {})",
        s.replicas, s.spp, defaultReplicas(s.spp)));
}

std::uint32_t defaultReplicas(std::uint32_t spp) {
  for (std::uint32_t k = std::min(spp, kDefaultMaxReplicas); k > 1; --k)
    if (spp % k == 0) return k;
  return spp;
}

const char* samplerName(SamplerKind kind) {
  return kind == SamplerKind::kSobol ? "sobol" : "independent";
}

SamplerKind parseSamplerName(const std::string& name) {
  if (name == "sobol") return SamplerKind::kSobol;
  if (name == "independent") return SamplerKind::kIndependent;
  throw InputError(fmt::format(
      "unknown sampler '{}'; give sobol (low discrepancy, the default) or independent", name));
}

const char* pixelSamplingName(PixelSampling sampling) {
  return sampling == PixelSampling::kCenter ? "center" : "area";
}

PixelSampling parsePixelSampling(const std::string& name) {
  if (name == "area") return PixelSampling::kArea;
  if (name == "center") return PixelSampling::kCenter;
  throw InputError(fmt::format(
      "unknown pixel sampling '{}'; give center (camera rays through pixel centres, as a "
      "rasteriser samples) or area (a box filter over each pixel)",
      name));
}

std::uint32_t replicasOf(const RenderSettings& settings) {
  return settings.replicas > 0 ? settings.replicas : defaultReplicas(settings.spp);
}

const char* lightPathsName(LightPaths mode) {
  return mode == LightPaths::kOff ? "off" : "auto";
}

LightPaths parseLightPaths(const std::string& name) {
  if (name == "auto") return LightPaths::kAuto;
  if (name == "off") return LightPaths::kOff;
  throw InputError(fmt::format(
      "unknown light-paths mode '{}'; give auto (trace the caustics' paths from the lights when "
      "the scene has mirrors or glass) or off (camera paths only)",
      name));
}

bool tracesLightPaths(const scene::Scene& scene, LightPaths mode) {
  return mode == LightPaths::kAuto && LightTracer::applies(scene);
}

bool tracesLightPaths(const scene::Scene& scene, const RenderSettings& settings) {
  return !settings.obscurance && tracesLightPaths(scene, settings.light_paths);
}

std::vector<std::uint32_t> passBoundaries(std::uint32_t spp) {
  std::vector<std::uint32_t> ends;
  for (std::uint64_t n = 1; n < spp; n *= 2) ends.push_back(std::uint32_t(n));
  ends.push_back(spp);
  return ends;
}

RenderResult renderReference(const scene::Scene& scene, const RenderSettings& settings,
                             const CheckpointCallback& on_checkpoint) {
  validateRenderSettings(settings);
  const int width = settings.width;
  const int height = settings.height;
  const auto start = std::chrono::steady_clock::now();

  const bool light_paths = tracesLightPaths(scene, settings);
  // The light tracer splats through a pinhole (LightTracer); a lens would need its own importance.
  if (light_paths && scene.camera.lens_radius > 0)
    throw InputError(fmt::format(
        "scene '{}' has mirrors or glass, whose caustics the reference traces from the lights "
        "through a pinhole camera only; give lens radius 0, or --light-paths off to trace camera "
        "paths alone",
        scene.name));
  // An obscurance has no path class: the tracer lends it its BVH and triangles only.
  PathTracer tracer(scene, settings.obscurance ? PathClass{} : settings.path_class, light_paths,
                    settings.environment_occlusion);
  std::optional<ObscuranceEstimator> obscurance;
  if (settings.obscurance)
    obscurance.emplace(scene, *settings.obscurance, tracer.embree(), tracer.triangles());
  std::optional<LightTracer> light_tracer;
  if (light_paths) light_tracer.emplace(scene, tracer, width, height);
  const scene::CameraFrame camera = scene::makeCameraFrame(scene.camera, width, height);
  const std::vector<Tile> tiles = makeTiles(width, height);
  std::vector<PixelSums> sums(std::size_t(width) * height);
  const std::uint32_t replicas = replicasOf(settings);
  std::vector<double> replica_sums(replicas > 1 ? sums.size() * replicas * 3 : 0);
  std::atomic<std::uint64_t> rays{0};

  ProgressBar progress(
      "reference", std::uint64_t(settings.spp) * width * height * (light_paths ? 2 : 1), "samples");
  const bool show_progress = settings.progress;
  // Each pixel's samples are accumulated by one task in sample order, so the sums — and the
  // image — are the same whatever the number of threads or the order of the tiles.
  auto renderPass = [&](std::uint32_t first, std::uint32_t end) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tiles.size(), 1), [&](auto range) {
      std::uint64_t tile_rays = 0;
      CameraBatch batch;
      for (std::size_t t = range.begin(); t != range.end(); ++t) {
        const Tile& tile = tiles[t];
        for (int y = tile.y0; y < tile.y1; ++y)
          for (int x = tile.x0; x < tile.x1; ++x) {
            const auto pixel = std::size_t(y) * width + x;
            PixelSums& acc = sums[pixel];
            for (std::uint32_t batch_first = first; batch_first < end;
                 batch_first += kCameraBatch) {
              const std::uint32_t batch_end = std::min(end, batch_first + kCameraBatch);
              batch.trace(tracer, camera, settings, replicas, x, y, batch_first, batch_end);
              for (std::uint32_t s = batch_first; s < batch_end; ++s) {
                const RadianceSample r = obscurance ? batch.obscurance(*obscurance, s - batch_first)
                                                    : batch.radiance(tracer, s - batch_first);
                tile_rays += r.rays;
                double* replica =
                    replicas > 1 ? &replica_sums[(pixel * replicas + s % replicas) * 3] : nullptr;
                for (int c = 0; c < 3; ++c) {
                  acc.sum[c] += r.total[c];
                  acc.direct[c] += r.direct[c];
                  if (replica) replica[c] += r.total[c];
                }
              }
            }
          }
        if (show_progress)
          progress.advance(std::uint64_t(end - first) * (tile.x1 - tile.x0) * (tile.y1 - tile.y0));
      }
      rays += tile_rays;
    });
  };

  // Light paths: one per pixel slot and sample, so that sample s of the pass traces as many light
  // paths as camera paths. A path belongs to replica s % replicas like the slot's camera path.
  const std::uint64_t light_seed = splitMixFinalise(settings.seed ^ kLightPathSeedSalt);
  auto traceLightPaths = [&](std::uint32_t first, std::uint32_t end) {
    std::vector<std::vector<std::pair<LightSplat, std::uint32_t>>> tile_splats(tiles.size());
    for (std::uint32_t block = first; block < end; block += kLightPathBlock) {
      const std::uint32_t block_end = std::min(end, block + kLightPathBlock);
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tiles.size(), 1), [&](auto range) {
        std::uint64_t tile_rays = 0;
        std::vector<LightSplat> splats;
        for (std::size_t t = range.begin(); t != range.end(); ++t) {
          const Tile& tile = tiles[t];
          auto& out = tile_splats[t];
          out.clear();
          for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x)
              for (std::uint32_t s = block; s < block_end; ++s) {
                PathSampler sampler(light_seed, std::uint32_t(y * width + x), s, replicas,
                                    settings.sampler);
                splats.clear();
                tile_rays += light_tracer->trace(sampler, splats);
                for (const LightSplat& splat : splats) out.emplace_back(splat, s % replicas);
              }
          if (show_progress)
            progress.advance(std::uint64_t(block_end - block) * (tile.x1 - tile.x0) *
                             (tile.y1 - tile.y0));
        }
        rays += tile_rays;
      });
      for (const auto& out : tile_splats)
        for (const auto& [splat, replica] : out)
          for (int c = 0; c < 3; ++c) {
            sums[splat.pixel].sum[c] += splat.value[c];
            if (replicas > 1)
              replica_sums[(splat.pixel * replicas + replica) * 3 + c] += splat.value[c];
          }
    }
  };

  const int threads = resolveThreadCount(settings.threads);
  tbb::task_arena arena(threads);
  arena.execute([&] {
    std::uint32_t done = 0;
    for (std::uint32_t end : passBoundaries(settings.spp)) {
      renderPass(done, end);
      if (light_paths) traceLightPaths(done, end);
      done = end;
      if (on_checkpoint) on_checkpoint(done, meanImage(sums, width, height, done));
    }
  });
  if (show_progress) progress.finish();

  // Resolve the sums into images.
  RenderResult result;
  const std::uint32_t n = settings.spp;
  result.spp = n;
  result.light_paths = light_paths;
  result.replicas = replicas;
  result.variance_dof = replicas - 1;
  result.mean = meanImage(sums, width, height, n);
  result.direct = image::Image(width, height);
  result.indirect = image::Image(width, height);
  if (replicas > 1) result.variance = image::Image(width, height);
  const double per_replica = double(n / replicas);
  for (std::size_t i = 0; i < sums.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double mean = sums[i].sum[c] / n;
      const double direct = sums[i].direct[c] / n;
      result.direct.data()[3 * i + c] = float(direct);
      result.indirect.data()[3 * i + c] = float(mean - direct);
      if (replicas > 1) {
        // The replicas' means are independent estimates of the pixel, each of variance K·V
        // where V is the variance of their average: V = Σ(mᵣ − m)² / (K (K − 1)).
        double squares = 0;
        for (std::uint32_t k = 0; k < replicas; ++k) {
          const double d = replica_sums[(i * replicas + k) * 3 + c] / per_replica - mean;
          squares += d * d;
        }
        result.variance.data()[3 * i + c] = float(squares / (double(replicas) * (replicas - 1)));
      }
    }
  result.rays = rays.load();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace gib::ref
