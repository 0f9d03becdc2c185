#include "metrics/error_concentration.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace gib::metrics {

std::vector<ErrorConcentration> errorConcentrations(const image::Image& map,
                                                    std::span<const double> fractions) {
  std::vector<float> values;
  values.reserve(map.data().size());
  double total = 0;  // in pixel order: the same image gives the same sum
  for (float v : map.data())
    if (std::isfinite(v)) {
      values.push_back(v);
      total += v;
    }
  auto worstCount = [&](double fraction) {
    return std::min(values.size(), std::size_t(std::floor(fraction * double(values.size()))));
  };
  std::size_t most = 0;
  for (double fraction : fractions) most = std::max(most, worstCount(fraction));
  // Only the worst pixels are ordered (a selection, then a sort of the few): a full sort of a
  // megapixel map would cost fifteen times relMSE itself.
  const auto worst_end = values.begin() + std::ptrdiff_t(most);
  std::nth_element(values.begin(), worst_end, values.end(), std::greater<float>());
  std::sort(values.begin(), worst_end, std::greater<float>());
  std::vector<ErrorConcentration> result;
  for (double fraction : fractions) {
    ErrorConcentration c;
    c.fraction = fraction;
    c.worst = worstCount(fraction);
    double worst_sum = 0;
    for (std::size_t i = 0; i < c.worst; ++i) worst_sum += values[i];
    c.share = total > 0 ? worst_sum / total : 0.0;
    const std::size_t rest = values.size() - c.worst;
    c.mean_without = rest > 0 ? std::max(total - worst_sum, 0.0) / double(rest) : 0.0;
    result.push_back(c);
  }
  return result;
}

ErrorConcentration errorConcentration(const image::Image& map, double fraction) {
  return errorConcentrations(map, std::span(&fraction, 1)).front();
}

}  // namespace gib::metrics
