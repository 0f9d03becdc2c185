// A float image: the in-memory form of every render, reference and error map (docs/architecture.md,
// "Conventions", Images). Row-major, pixel (0,0) top-left, channels interleaved; three channels
// hold scene-linear Rec.709 RGB radiance unless a layer says otherwise.
#pragma once

#include "common/luminance_shared.h"

#include <cstddef>
#include <span>
#include <vector>

namespace gib::image {

class Image {
 public:
  // An empty 0×0 image with 3 channels.
  Image() = default;
  // Throws std::invalid_argument for a negative size or fewer than one channel.
  Image(int width, int height, int channels = 3, float fill = 0.0f);

  int width() const { return width_; }
  int height() const { return height_; }
  int channels() const { return channels_; }
  std::size_t pixelCount() const { return std::size_t(width_) * std::size_t(height_); }

  // The first of the pixel's channels. Coordinates are not checked (hot loops call this).
  float* pixel(int x, int y) { return values_.data() + offset(x, y); }
  const float* pixel(int x, int y) const { return values_.data() + offset(x, y); }

  // All values, pixel after pixel: width × height × channels floats.
  std::span<float> data() { return values_; }
  std::span<const float> data() const { return values_; }

  // Same width, height and channel count.
  bool sameSize(const Image& other) const;

 private:
  std::size_t offset(int x, int y) const {
    return (std::size_t(y) * std::size_t(width_) + std::size_t(x)) * std::size_t(channels_);
  }

  int width_ = 0;
  int height_ = 0;
  int channels_ = 3;
  std::vector<float> values_;
};

// Pixels with at least one NaN or infinite channel; a renderer that produces any has a bug, and
// every error metric would silently turn into NaN.
std::size_t countNonFinite(const Image& image);

// The luminance of linear Rec.709 RGB (ITU-R BT.709 weights, common/luminance_shared.h).
inline float rec709Luminance(const float* rgb) {
  return float(kLuminanceRed) * rgb[0] + float(kLuminanceGreen) * rgb[1] +
         float(kLuminanceBlue) * rgb[2];
}

}  // namespace gib::image
