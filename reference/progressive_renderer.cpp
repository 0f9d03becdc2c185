#include "reference/progressive_renderer.h"

#include "common/input_error.h"
#include "common/progress.h"
#include "scene/camera.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <fmt/format.h>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

namespace gib::ref {

namespace {

constexpr int kTileSize = 16;

// Running sums per pixel, in double so that millions of samples do not lose precision.
struct PixelSums {
  double sum[3] = {0, 0, 0};
  double sum_squares[3] = {0, 0, 0};
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

  PathTracer tracer(scene, settings.path_class);
  const scene::CameraFrame camera = scene::makeCameraFrame(scene.camera, width, height);
  const std::vector<Tile> tiles = makeTiles(width, height);
  std::vector<PixelSums> sums(std::size_t(width) * height);
  std::atomic<std::uint64_t> rays{0};

  ProgressBar progress("reference", std::uint64_t(settings.spp) * width * height, "samples");
  const bool show_progress = settings.progress;
  // Each pixel's samples are accumulated by one task in sample order, so the sums — and the
  // image — are the same whatever the number of threads or the order of the tiles.
  auto renderPass = [&](std::uint32_t first, std::uint32_t end) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tiles.size(), 1), [&](auto range) {
      std::uint64_t tile_rays = 0;
      for (std::size_t t = range.begin(); t != range.end(); ++t) {
        const Tile& tile = tiles[t];
        for (int y = tile.y0; y < tile.y1; ++y)
          for (int x = tile.x0; x < tile.x1; ++x) {
            const auto pixel = std::uint32_t(y * width + x);
            PixelSums& acc = sums[pixel];
            for (std::uint32_t s = first; s < end; ++s) {
              SampleStream random(settings.seed, pixel, s);
              // Box filter: a uniform point in the pixel.
              float px = float(x) + random.next();
              float py = float(y) + random.next();
              glm::vec3 dir = scene::cameraRayDirection(camera, width, height, px, py);
              RadianceSample r = tracer.radiance(camera.origin, dir, random);
              tile_rays += r.rays;
              for (int c = 0; c < 3; ++c) {
                acc.sum[c] += r.total[c];
                acc.sum_squares[c] += double(r.total[c]) * r.total[c];
                acc.direct[c] += r.direct[c];
              }
            }
          }
        if (show_progress)
          progress.advance(std::uint64_t(end - first) * (tile.x1 - tile.x0) * (tile.y1 - tile.y0));
      }
      rays += tile_rays;
    });
  };

  const int threads = settings.threads > 0 ? settings.threads
                                           : int(std::max(1u, std::thread::hardware_concurrency()));
  tbb::task_arena arena(threads);
  arena.execute([&] {
    std::uint32_t done = 0;
    for (std::uint32_t end : passBoundaries(settings.spp)) {
      renderPass(done, end);
      done = end;
      if (on_checkpoint) on_checkpoint(done, meanImage(sums, width, height, done));
    }
  });
  if (show_progress) progress.finish();

  // Resolve the sums into images.
  RenderResult result;
  const std::uint32_t n = settings.spp;
  result.spp = n;
  result.mean = meanImage(sums, width, height, n);
  result.direct = image::Image(width, height);
  result.indirect = image::Image(width, height);
  if (n >= 2) result.variance = image::Image(width, height);
  for (std::size_t i = 0; i < sums.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double mean = sums[i].sum[c] / n;
      const double direct = sums[i].direct[c] / n;
      result.direct.data()[3 * i + c] = float(direct);
      result.indirect.data()[3 * i + c] = float(mean - direct);
      if (n >= 2) {
        // Unbiased sample variance, divided by n for the variance of the mean.
        double sample_variance = (sums[i].sum_squares[c] - n * mean * mean) / (n - 1);
        result.variance.data()[3 * i + c] = float(std::max(0.0, sample_variance) / n);
      }
    }
  result.rays = rays.load();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace gib::ref
