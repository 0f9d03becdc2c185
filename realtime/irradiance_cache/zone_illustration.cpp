#include "realtime/irradiance_cache/zone_illustration.h"

#include "common/splitmix.h"

#include <glm/vec4.hpp>

#include <cmath>
#include <limits>

namespace gib::rt {

namespace {

// A bright, saturated colour per record: distinct neighbours, the same on every run.
glm::vec3 recordColour(std::size_t index) {
  const std::uint64_t bits = splitMixFinalise(std::uint64_t(index) + 1);
  const float hue = float(bits & 0xffff) / 65536.0f * 6.0f;
  const float x = 1.0f - std::abs(std::fmod(hue, 2.0f) - 1.0f);
  const int sector = int(hue);
  const glm::vec3 rgb = sector == 0   ? glm::vec3(1, x, 0)
                        : sector == 1 ? glm::vec3(x, 1, 0)
                        : sector == 2 ? glm::vec3(0, 1, x)
                        : sector == 3 ? glm::vec3(0, x, 1)
                        : sector == 4 ? glm::vec3(x, 0, 1)
                                      : glm::vec3(1, 0, x);
  return 0.25f + 0.6f * rgb;
}

}  // namespace

image::Image zoneIllustration(const SurfaceImage& surfaces, const CameraTransform& camera,
                              std::span<const gpu::IrradianceRecord> records, float accuracy) {
  const int width = surfaces.width, height = surfaces.height;
  // Per pixel: the heaviest weight there, its record, and the record whose own pixel it is.
  struct Pixel {
    float best = 0;
    std::int32_t owner = -1, centre = -1;
  };
  std::vector<Pixel> pixels(std::size_t(width) * std::size_t(height));
  for (std::size_t k = 0; k < records.size(); ++k) {
    const gpu::IrradianceRecord& record = records[k];
    const glm::ivec4 rect = zonePixelRect(camera, width, height, record, accuracy);
    float heaviest = 0;
    std::size_t heaviest_pixel = 0;
    for (int y = rect.y; y <= rect.w; ++y)
      for (int x = rect.x; x <= rect.z; ++x) {
        const std::size_t i = surfaces.index(x, y);
        if (!surfaces.valid[i]) continue;
        const float w = gpu::recordWeight(record, surfaces.position[i], surfaces.normal[i]);
        if (w <= 1.0f / accuracy) continue;
        if (w > pixels[i].best) {
          pixels[i].best = w;
          pixels[i].owner = std::int32_t(k);
        }
        if (w > heaviest) {
          heaviest = w;
          heaviest_pixel = i;
        }
      }
    if (heaviest > 0) pixels[heaviest_pixel].centre = std::int32_t(k);
  }
  image::Image picture(width, height, 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = surfaces.index(x, y);
      glm::vec3 colour(0.0f);
      if (pixels[i].owner >= 0) colour = recordColour(std::size_t(pixels[i].owner));
      // The record's own pixel and its four neighbours: a small white cross.
      bool marked = pixels[i].centre >= 0;
      for (int d = -1; d <= 1 && !marked; d += 2) {
        if (x + d >= 0 && x + d < width && pixels[surfaces.index(x + d, y)].centre >= 0)
          marked = true;
        if (y + d >= 0 && y + d < height && pixels[surfaces.index(x, y + d)].centre >= 0)
          marked = true;
      }
      if (marked) colour = glm::vec3(1.0f);
      float* out = picture.pixel(x, height - 1 - y);
      for (int c = 0; c < 3; ++c) out[c] = colour[c];
    }
  return picture;
}

DeclaredOutput zonesImageDeclaration() {
  return {"zones",
          "the records' zones of influence: each pixel in the colour of the record that weighs "
          "most there, records' pixels white"};
}

AuxiliaryImage zonesAuxiliaryImage(const SurfaceImage& surfaces, const CameraTransform& camera,
                                   std::span<const gpu::IrradianceRecord> records, float accuracy) {
  DeclaredOutput zones = zonesImageDeclaration();
  return {std::move(zones.name), std::move(zones.description),
          zoneIllustration(surfaces, camera, records, accuracy)};
}

}  // namespace gib::rt
