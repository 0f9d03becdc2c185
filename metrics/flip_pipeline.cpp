#include "metrics/flip_pipeline.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "metrics/flip_color.h"

namespace gib::metrics::flip_detail {
namespace {

// Colour pipeline (FLIP paper, colour metric): the HyAB distance is raised to q_c, then mapped
// to [0, 1] so that distances below p_c·c_max take [0, p_t] and the rest (p_t, 1], compressing
// the large differences the eye ranks together.
constexpr float kColorExponent = 0.7f;        // q_c
constexpr float kColorCutoffFraction = 0.4f;  // p_c
constexpr float kColorCutoffMapsTo = 0.95f;   // p_t
// Feature pipeline (FLIP paper, feature metric): the larger of the edge and point differences,
// scaled by 1/√2 (the largest a difference of two gradient magnitudes of unit-normalised filters
// can be) and raised to q_f.
constexpr float kFeatureExponent = 0.5f;  // q_f
const float kFeatureScale = float(1.0 / std::sqrt(2.0));

// c_max: the distance between the most different displayable colours, pure green and pure blue,
// Hunt-adjusted and raised to q_c (FLIP paper, colour metric).
float maxColorDistance() {
  const float green[3] = {0, 1, 0};
  const float blue[3] = {0, 0, 1};
  return std::pow(hyAb(linearRgbToHuntLab(green), linearRgbToHuntLab(blue)), kColorExponent);
}

// Rows are split among threads; every pixel's value depends only on its inputs, never on the
// split, so results are bit-identical for any thread count.
template <typename Body>
void forEachRowBlock(int height, const Body& body) {
  tbb::parallel_for(tbb::blocked_range<int>(0, height, 8), body);
}

}  // namespace

LdrFlipEvaluator::LdrFlipEvaluator(int width, int height, float pixels_per_degree)
    : width_(width),
      height_(height),
      spatial_(makeSpatialKernels(pixels_per_degree)),
      feature_(makeFeatureKernels(pixels_per_degree)) {
  const std::size_t size = std::size_t(width) * std::size_t(height);
  for (OpponentImage& image : images_) {
    image.y.resize(size);
    image.cx.resize(size);
    image.cz.resize(size);
  }
  for (auto& planes : row_passes_)
    for (auto& plane : planes) plane.resize(size);
}

void LdrFlipEvaluator::evaluate(float* error) {
  computeColorDifference(error);
  combineWithFeatureDifference(error);
}

void LdrFlipEvaluator::computeColorDifference(float* color_difference) {
  const int w = width_;
  const int h = height_;
  const std::size_t stride = std::size_t(w);

  // Step 1: row passes of the contrast sensitivity filters, both images.
  const int radius = spatial_.y.radius;
  forEachRowBlock(h, [&](const tbb::blocked_range<int>& rows) {
    std::vector<float> padded(std::size_t(w + 2 * radius));
    for (int y = rows.begin(); y != rows.end(); ++y) {
      const std::size_t row = std::size_t(y) * stride;
      for (int i = 0; i < 2; ++i) {
        const OpponentImage& image = images_[std::size_t(i)];
        auto& out = row_passes_[std::size_t(i)];
        padRow(image.y.data() + row, w, radius, padded.data());
        convolvePaddedRow(padded.data(), w, spatial_.y, out[0].data() + row);
        padRow(image.cx.data() + row, w, radius, padded.data());
        convolvePaddedRow(padded.data(), w, spatial_.cx, out[1].data() + row);
        padRow(image.cz.data() + row, w, radius, padded.data());
        convolvePaddedRow(padded.data(), w, spatial_.cz_first, out[2].data() + row);
        convolvePaddedRow(padded.data(), w, spatial_.cz_second, out[3].data() + row);
      }
    }
  });

  // Step 2: column passes, then per pixel: back to RGB clamped to the display's gamut, to
  // Hunt-adjusted CIELab, HyAB distance, and the mapping to [0, 1].
  const float cmax = maxColorDistance();
  const float cutoff = kColorCutoffFraction * cmax;
  forEachRowBlock(h, [&](const tbb::blocked_range<int>& rows) {
    std::array<std::array<std::vector<float>, 4>, 2> filtered;
    for (auto& image : filtered)
      for (auto& channel : image) channel.resize(stride);
    for (int y = rows.begin(); y != rows.end(); ++y) {
      for (std::size_t i = 0; i < 2; ++i) {
        convolveColumn(row_passes_[i][0].data(), w, h, y, spatial_.y, filtered[i][0].data());
        convolveColumn(row_passes_[i][1].data(), w, h, y, spatial_.cx, filtered[i][1].data());
        convolveColumn(row_passes_[i][2].data(), w, h, y, spatial_.cz_first, filtered[i][2].data());
        convolveColumn(row_passes_[i][3].data(), w, h, y, spatial_.cz_second,
                       filtered[i][3].data());
      }
      float* out = color_difference + std::size_t(y) * stride;
      for (int x = 0; x < w; ++x) {
        Lab lab[2];
        for (std::size_t i = 0; i < 2; ++i) {
          const auto& f = filtered[i];
          const Opponent o{f[0][x], f[1][x], f[2][x] + f[3][x]};
          float rgb[3];
          opponentToClampedLinearRgb(o, rgb);
          lab[i] = linearRgbToHuntLab(rgb);
        }
        const float distance = std::pow(hyAb(lab[0], lab[1]), kColorExponent);
        const float mapped = distance < cutoff
                                 ? distance * (kColorCutoffMapsTo / cutoff)
                                 : kColorCutoffMapsTo + (distance - cutoff) / (cmax - cutoff) *
                                                            (1.0f - kColorCutoffMapsTo);
        // Green against blue is the largest distance in the gamut, so only rounding can pass 1.
        out[x] = std::min(mapped, 1.0f);
      }
    }
  });
}

void LdrFlipEvaluator::combineWithFeatureDifference(float* error) {
  const int w = width_;
  const int h = height_;
  const std::size_t stride = std::size_t(w);

  // Step 1: row passes of the feature detectors on the achromatic channel, normalised to [0, 1]
  // ((Y + 16) / 116, i.e. relative luminance): first and second derivative of the Gaussian for
  // the x-filters, the Gaussian itself for the y-filters' other axis.
  const int radius = feature_.gaussian.radius;
  forEachRowBlock(h, [&](const tbb::blocked_range<int>& rows) {
    std::vector<float> luminance(stride);
    std::vector<float> padded(std::size_t(w + 2 * radius));
    for (int y = rows.begin(); y != rows.end(); ++y) {
      const std::size_t row = std::size_t(y) * stride;
      for (std::size_t i = 0; i < 2; ++i) {
        const float* achromatic = images_[i].y.data() + row;
        for (int x = 0; x < w; ++x)
          luminance[std::size_t(x)] = achromatic[x] * (1.0f / 116.0f) + 16.0f / 116.0f;
        padRow(luminance.data(), w, radius, padded.data());
        auto& out = row_passes_[i];
        convolvePaddedRow(padded.data(), w, feature_.first, out[0].data() + row);
        convolvePaddedRow(padded.data(), w, feature_.second, out[1].data() + row);
        convolvePaddedRow(padded.data(), w, feature_.gaussian, out[2].data() + row);
      }
    }
  });

  // Step 2: column passes giving the x and y responses of the edge (first derivative) and point
  // (second derivative) detectors; the feature difference compares their magnitudes, and the
  // error is the colour difference raised to 1 − feature difference, so that a feature
  // difference pulls a small colour difference up.
  forEachRowBlock(h, [&](const tbb::blocked_range<int>& rows) {
    // Per image: edge x, point x, edge y, point y.
    std::array<std::array<std::vector<float>, 4>, 2> responses;
    for (auto& image : responses)
      for (auto& response : image) response.resize(stride);
    for (int y = rows.begin(); y != rows.end(); ++y) {
      for (std::size_t i = 0; i < 2; ++i) {
        const auto& in = row_passes_[i];
        auto& out = responses[i];
        convolveColumn(in[0].data(), w, h, y, feature_.gaussian, out[0].data());
        convolveColumn(in[1].data(), w, h, y, feature_.gaussian, out[1].data());
        convolveColumn(in[2].data(), w, h, y, feature_.first, out[2].data());
        convolveColumn(in[2].data(), w, h, y, feature_.second, out[3].data());
      }
      float* out = error + std::size_t(y) * stride;
      for (int x = 0; x < w; ++x) {
        float edge[2], point[2];
        for (std::size_t i = 0; i < 2; ++i) {
          const auto& r = responses[i];
          edge[i] = std::sqrt(r[0][x] * r[0][x] + r[2][x] * r[2][x]);
          point[i] = std::sqrt(r[1][x] * r[1][x] + r[3][x] * r[3][x]);
        }
        const float difference =
            std::max(std::fabs(edge[0] - edge[1]), std::fabs(point[0] - point[1]));
        const float feature = std::pow(kFeatureScale * difference, kFeatureExponent);
        out[x] = std::pow(out[x], 1.0f - feature);
      }
    }
  });
}

}  // namespace gib::metrics::flip_detail
