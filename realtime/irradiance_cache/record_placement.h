// Where the irradiance cache needs records (course notes 001, "record detection"): the notes'
// traversal of the visible points, which creates a record wherever no record yet contributes and
// splats each new record's weight over its zone of influence, so that a later record also covers
// pixels checked before it (no order constraint). Shared by the CPU cache and the GPU splatting,
// so both place the same records for the same image and accuracy.
//
// The notes create one record at a time; both implementations here compute records in batches
// (GPU views in layers, CPU rays on every core), so the traversal goes in rounds: the pixels of a
// grid, coarse to fine (spacing halves each round down to one pixel, then stays), that no record
// covers become the round's records, except those within `min_zone_pixels` of one accepted in the
// same round (its zone will cover them at least that far, or the next round takes them). Every
// round covers its records' own pixels, so rounds end when every pixel is covered. The notes'
// own scanline traversal (one record per round) is kept to measure what the rounds cost in records.
#pragma once

#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/irradiance_cache/irradiance_cache_shared.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace gib::rt {

// What the camera sees at each pixel, GL row order (row 0 at the bottom, as NDC y = −1): position
// and unit normal on the viewer's side where `valid`.
struct SurfaceImage {
  int width = 0, height = 0;
  std::vector<glm::vec3> position, normal;
  std::vector<std::uint8_t> valid;

  std::size_t index(int x, int y) const { return std::size_t(y) * std::size_t(width) + x; }
};

struct RecordPlacementSettings {
  float accuracy = 0.2f;      // Ward's a: a record contributes where w > 1/a
  int coarsest_spacing = 32;  // pixels between the first round's candidates
  // The notes' own traversal instead: the pixels in scan order, one record at a time, each
  // splatted before the next pixel is checked (a round of one record).
  bool scanline = false;
  // A record's zone radius a·R is kept between these many pixel footprints at its distance: no
  // zone smaller than a few pixels in corners (R → 0), none larger than a part of the image.
  float min_zone_pixels = 2.0f;
  float max_zone_pixels = 64.0f;
};

class RecordPlacement {
 public:
  RecordPlacement(const SurfaceImage& surfaces, const CameraTransform& camera,
                  const RecordPlacementSettings& settings);

  // The pixels that get records this round (empty once every pixel is covered).
  std::vector<glm::ivec2> nextRound();
  // Clamps each record's R to the zone limits at its distance and splats its weight over its
  // zone. Records are added in the order of their round's pixels.
  void add(std::span<gpu::IrradianceRecord> records);

  // Sum of the weights above 1/a per pixel (GL row order): zero where no record contributes.
  const std::vector<float>& weights() const { return weights_; }
  int rounds() const { return rounds_; }

 private:
  const SurfaceImage& surfaces_;
  CameraTransform camera_;
  RecordPlacementSettings settings_;
  float pixel_angle_;  // a pixel's side over its distance, at the image centre
  std::vector<float> weights_;
  int spacing_;
  int rounds_ = 0;
  std::size_t cursor_ = 0;  // scanline: the next pixel to check
};

// The pixels (x0, y0, x1, y1 inclusive; x1 < x0 when none) whose centres lie in the zone rectangle
// of a record: sphereScreenRect converted to a width × height image in GL row order.
glm::ivec4 zonePixelRect(const CameraTransform& camera, int width, int height,
                         const gpu::IrradianceRecord& record, float accuracy);

}  // namespace gib::rt
