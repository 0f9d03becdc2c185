#include "image/image.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace gib::image {

Image::Image(int width, int height, int channels, float fill)
    : width_(width), height_(height), channels_(channels) {
  if (width < 0 || height < 0 || channels < 1)
    throw std::invalid_argument("Image: invalid size " + std::to_string(width) + "x" +
                                std::to_string(height) + "x" + std::to_string(channels));
  values_.assign(pixelCount() * std::size_t(channels), fill);
}

bool Image::sameSize(const Image& other) const {
  return width_ == other.width_ && height_ == other.height_ && channels_ == other.channels_;
}

std::size_t countNonFinite(const Image& image) {
  const std::span<const float> values = image.data();
  const auto channels = std::size_t(image.channels());
  std::size_t count = 0;
  for (std::size_t start = 0; start < values.size(); start += channels) {
    for (std::size_t c = 0; c < channels; ++c) {
      if (!std::isfinite(values[start + c])) {
        ++count;
        break;
      }
    }
  }
  return count;
}

}  // namespace gib::image
