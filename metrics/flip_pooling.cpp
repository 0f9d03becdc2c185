// Pooling of a FLIP error map into the statistics the published tool prints.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <span>
#include <vector>

#include "metrics/flip_pipeline.h"

namespace gib::metrics::flip_detail {
namespace {

// Weighted percentiles as the published tool defines them (FLIP paper, pooling; NVlabs/flip
// v1.6, pooling.h): with the errors sorted ascending, the p-th one is the first error at which
// the running sum exceeds p times the total.
//
// A full sort of a megapixel map costs more than the rest of the pooling, so the errors are first
// binned by the top 16 bits of their float representation: for non-negative floats that order
// is the order of the values, so the bins are consecutive value ranges. Only the bin where the
// running sum crosses p·total is sorted. Sums run in index order, then bin order: deterministic.
constexpr int kBinShift = 16;

std::uint32_t binOf(float value) {
  return std::bit_cast<std::uint32_t>(value) >> kBinShift;
}

template <std::size_t N>
std::array<double, N> weightedPercentiles(std::span<const float> errors,
                                          const std::array<double, N>& fractions) {
  std::array<double, N> result{};
  std::vector<double> bin_sums(std::size_t(1) << (32 - kBinShift), 0.0);
  double total = 0;
  for (float e : errors) {
    bin_sums[binOf(e)] += e;
    total += e;
  }
  if (!(total > 0)) return result;  // every error 0: so is every percentile

  for (std::size_t n = 0; n < N; ++n) {
    const double target = fractions[n] * total;
    // Step 1: the bin in which the running sum passes the target.
    double running = 0;
    std::uint32_t bin = 0;
    while (bin + 1 < bin_sums.size() && running + bin_sums[bin] <= target)
      running += bin_sums[bin++];
    // Step 2: the error within that bin, in sorted order.
    std::vector<float> members;
    for (float e : errors)
      if (binOf(e) == bin) members.push_back(e);
    std::sort(members.begin(), members.end());
    result[n] = members.empty() ? 0.0 : double(members.back());
    for (float e : members) {
      running += e;
      if (running > target) {
        result[n] = e;
        break;
      }
    }
  }
  return result;
}

}  // namespace

void poolErrors(FlipResult& result) {
  const image::Image& map = result.error_map;
  const int w = map.width();
  const int h = map.height();
  const std::span<const float> errors = map.data();

  // Row sums in double in parallel, added in row order: the same mean for any thread count.
  std::vector<double> row_sums(std::size_t(h), 0.0);
  std::vector<float> row_min(static_cast<std::size_t>(h)), row_max(static_cast<std::size_t>(h));
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 16), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y != rows.end(); ++y) {
      const float* row = map.pixel(0, y);
      double sum = 0;
      float lo = row[0], hi = row[0];
      for (int x = 0; x < w; ++x) {
        sum += row[x];
        lo = std::min(lo, row[x]);
        hi = std::max(hi, row[x]);
      }
      row_sums[std::size_t(y)] = sum;
      row_min[std::size_t(y)] = lo;
      row_max[std::size_t(y)] = hi;
    }
  });
  double sum = 0;
  for (double s : row_sums) sum += s;
  result.mean = sum / double(errors.size());
  result.minimum = *std::min_element(row_min.begin(), row_min.end());
  result.maximum = *std::max_element(row_max.begin(), row_max.end());

  const auto quartiles = weightedPercentiles(errors, std::array<double, 3>{0.25, 0.5, 0.75});
  result.weighted_first_quartile = quartiles[0];
  result.weighted_median = quartiles[1];
  result.weighted_third_quartile = quartiles[2];
}

}  // namespace gib::metrics::flip_detail
