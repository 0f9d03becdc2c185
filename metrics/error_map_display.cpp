#include "metrics/error_map_display.h"

#include "image/false_color.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace gib::metrics {

std::pair<float, float> errorMapDisplayRange(const std::string& metric, const image::Image& map) {
  if (metric == "flip" || metric == "hdrflip" || metric == "ssim") return {0.0f, 1.0f};
  std::vector<float> values;
  for (float v : map.data())
    if (std::isfinite(v)) values.push_back(v);
  if (values.empty()) return {0.0f, 1.0f};
  auto k = values.begin() + std::ptrdiff_t(0.99 * double(values.size() - 1));
  std::nth_element(values.begin(), k, values.end());
  return {0.0f, *k > 0 ? *k : 1.0f};
}

image::Image errorMapForDisplay(const std::string& metric, const image::Image& map) {
  const auto [low, high] = errorMapDisplayRange(metric, map);
  return image::falseColorWithBar(map, low, high);
}

image::Image absoluteLuminanceDifference(const image::Image& reference, const image::Image& test) {
  if (reference.width() != test.width() || reference.height() != test.height() ||
      reference.channels() < 3 || test.channels() < 3)
    throw std::invalid_argument("absoluteLuminanceDifference needs two RGB images of one size");
  image::Image difference(reference.width(), reference.height(), 1);
  for (int y = 0; y < reference.height(); ++y)
    for (int x = 0; x < reference.width(); ++x)
      *difference.pixel(x, y) = std::abs(image::rec709Luminance(test.pixel(x, y)) -
                                         image::rec709Luminance(reference.pixel(x, y)));
  return difference;
}

}  // namespace gib::metrics
