#include "metrics/flip.h"

#include "common/luminance_shared.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "metrics/flip_color.h"
#include "metrics/flip_pipeline.h"

namespace gib::metrics {
namespace {

using flip_detail::LdrFlipEvaluator;
using flip_detail::OpponentImage;

// ACES filmic tone curve as Narkowicz's rational fit, x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14),
// evaluated at x = 0.6·c to cancel the 0.6 pre-exposure the fit has built in: the tone mapper
// HDR-FLIP uses by default (HDR-FLIP paper; NVlabs/flip v1.6). Written as
// (k0·c² + k1·c) / (k3·c² + k4·c + k5).
constexpr float kAcesK0 = 0.6f * 0.6f * 2.51f;
constexpr float kAcesK1 = 0.6f * 0.03f;
constexpr float kAcesK3 = 0.6f * 0.6f * 2.43f;
constexpr float kAcesK4 = 0.6f * 0.59f;
constexpr float kAcesK5 = 0.14f;
// |c| above this is clamped before tone mapping: c² stays finite in float.
constexpr double kToneMapInputBound = 1e18;
// The exposure range maps the reference's maximum and median luminance to this tone-mapped
// value (HDR-FLIP paper, exposure range; NVlabs/flip v1.6).
constexpr double kExposureTarget = 0.85;

void checkInputs(const image::Image& reference, const image::Image& test) {
  if (reference.width() != test.width() || reference.height() != test.height())
    throw std::invalid_argument("FLIP needs images of equal size; the reference is " +
                                std::to_string(reference.width()) + "×" +
                                std::to_string(reference.height()) + " and the test " +
                                std::to_string(test.width()) + "×" + std::to_string(test.height()));
  if (reference.channels() < 3 || test.channels() < 3)
    throw std::invalid_argument("FLIP needs RGB images (at least three channels)");
  if (reference.pixelCount() == 0) throw std::invalid_argument("FLIP of empty images");
}

// A pixel with a NaN or infinite channel becomes black (flip.h explains why).
bool isFinitePixel(const float* p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

// An image's RGB as three planes, non-finite pixels already black: the form the per-exposure
// conversion reads without branches, so that it vectorises.
struct RgbPlanes {
  int width = 0;
  int height = 0;
  std::vector<float> r, g, b;
};

RgbPlanes toFiniteRgbPlanes(const image::Image& source) {
  RgbPlanes planes{source.width(), source.height(), {}, {}, {}};
  planes.r.resize(source.pixelCount());
  planes.g.resize(source.pixelCount());
  planes.b.resize(source.pixelCount());
  tbb::parallel_for(
      tbb::blocked_range<int>(0, source.height(), 16), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y != rows.end(); ++y)
          for (int x = 0; x < source.width(); ++x) {
            const float* p = source.pixel(x, y);
            const bool finite = isFinitePixel(p);
            const std::size_t i = std::size_t(y) * std::size_t(planes.width) + std::size_t(x);
            planes.r[i] = finite ? p[0] : 0.0f;
            planes.g[i] = finite ? p[1] : 0.0f;
            planes.b[i] = finite ? p[2] : 0.0f;
          }
      });
  return planes;
}

// Converts `source` into YyCxCz planes after `transform` maps each RGB value to display RGB,
// clamped to [0, 1].
template <typename Transform>
void toOpponent(const RgbPlanes& source, const Transform& transform, OpponentImage& out) {
  const std::size_t w = std::size_t(source.width);
  tbb::parallel_for(
      tbb::blocked_range<int>(0, source.height, 16), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y != rows.end(); ++y)
          for (std::size_t i = std::size_t(y) * w; i < std::size_t(y + 1) * w; ++i) {
            const flip_detail::Opponent o =
                flip_detail::linearRgbToOpponent(std::clamp(transform(source.r[i]), 0.0f, 1.0f),
                                                 std::clamp(transform(source.g[i]), 0.0f, 1.0f),
                                                 std::clamp(transform(source.b[i]), 0.0f, 1.0f));
            out.y[i] = o.y;
            out.cx[i] = o.cx;
            out.cz[i] = o.cz;
          }
      });
}

float checkedPixelsPerDegree(const FlipViewingConditions& viewing) {
  if (!(viewing.pixels_per_degree > 0) || !std::isfinite(viewing.pixels_per_degree))
    throw std::invalid_argument("FLIP needs a positive, finite pixels_per_degree");
  return float(viewing.pixels_per_degree);
}

// The larger root of (k0 − t·k3)x² + (k1 − t·k4)x − t·k5 = 0: the radiance the ACES curve maps
// to t.
double acesInverse(double t) {
  const double a = double(kAcesK0) - t * double(kAcesK3);
  const double b = double(kAcesK1) - t * double(kAcesK4);
  const double c = -t * double(kAcesK5);
  const double half_b_over_a = -0.5 * b / a;
  return half_b_over_a + std::sqrt(half_b_over_a * half_b_over_a - c / a);
}

}  // namespace

double flipPixelsPerDegree(double distance_m, double display_width_m,
                           double horizontal_resolution_px) {
  return distance_m * (horizontal_resolution_px / display_width_m) * std::numbers::pi / 180.0;
}

FlipResult computeLdrFlip(const image::Image& reference, const image::Image& test,
                          const FlipViewingConditions& viewing) {
  checkInputs(reference, test);
  LdrFlipEvaluator evaluator(reference.width(), reference.height(),
                             checkedPixelsPerDegree(viewing));
  const auto display = [](float v) { return v; };
  toOpponent(toFiniteRgbPlanes(reference), display, evaluator.reference());
  toOpponent(toFiniteRgbPlanes(test), display, evaluator.test());

  FlipResult result;
  result.error_map = image::Image(reference.width(), reference.height(), 1);
  evaluator.evaluate(result.error_map.data().data());
  flip_detail::poolErrors(result);
  return result;
}

FlipExposureRange computeFlipExposureRange(const image::Image& reference) {
  // Step 1: the luminances, non-finite pixels as black.
  std::vector<double> luminance;
  luminance.reserve(reference.pixelCount());
  double smallest_positive = std::numeric_limits<double>::infinity();
  for (int y = 0; y < reference.height(); ++y)
    for (int x = 0; x < reference.width(); ++x) {
      const float* p = reference.pixel(x, y);
      const double l = isFinitePixel(p)
                           ? kLuminanceRed * p[0] + kLuminanceGreen * p[1] + kLuminanceBlue * p[2]
                           : 0.0;
      luminance.push_back(l);
      if (l > 0) smallest_positive = std::min(smallest_positive, l);
    }
  FlipExposureRange range;
  range.exposure_count = 2;
  if (luminance.empty() || !std::isfinite(smallest_positive)) return range;

  // Step 2: maximum and (upper) median, stand-ins for non-positive ones.
  const auto median = luminance.begin() + std::ptrdiff_t(luminance.size() / 2);
  std::nth_element(luminance.begin(), median, luminance.end());
  const double y_median = *median > 0 ? *median : smallest_positive;
  const double y_max = *std::max_element(luminance.begin(), luminance.end());

  // Step 3: the exposures that bring them to the target after tone mapping.
  const double x_target = acesInverse(kExposureTarget);
  range.start_exposure = std::log2(x_target / y_max);
  range.stop_exposure = std::log2(x_target / y_median);
  range.exposure_count = int(std::max(2.0, std::ceil(range.stop_exposure - range.start_exposure)));
  return range;
}

FlipResult computeHdrFlip(const image::Image& reference, const image::Image& test,
                          const FlipViewingConditions& viewing, const HdrFlipOptions& options) {
  checkInputs(reference, test);
  const float ppd = checkedPixelsPerDegree(viewing);

  // Step 1: the exposure range, automatic where no option overrides it.
  FlipExposureRange range;
  if (!options.start_exposure || !options.stop_exposure || !options.exposure_count)
    range = computeFlipExposureRange(reference);
  range.start_exposure = options.start_exposure.value_or(range.start_exposure);
  range.stop_exposure = options.stop_exposure.value_or(range.stop_exposure);
  if (!std::isfinite(range.start_exposure) || !std::isfinite(range.stop_exposure))
    throw std::invalid_argument("HDR-FLIP needs finite start and stop exposures");
  if (range.start_exposure > range.stop_exposure)
    throw std::invalid_argument(
        "HDR-FLIP's start exposure (" + std::to_string(range.start_exposure) +
        ") must not exceed its stop exposure (" + std::to_string(range.stop_exposure) + ")");
  range.exposure_count = options.exposure_count.value_or(
      int(std::max(2.0, std::ceil(range.stop_exposure - range.start_exposure))));
  if (range.exposure_count < 1) throw std::invalid_argument("HDR-FLIP needs at least one exposure");

  // Step 2: LDR-FLIP of each exposure, tone-mapped, keeping the per-pixel maximum.
  const int w = reference.width();
  const int h = reference.height();
  LdrFlipEvaluator evaluator(w, h, ppd);
  const RgbPlanes reference_rgb = toFiniteRgbPlanes(reference);
  const RgbPlanes test_rgb = toFiniteRgbPlanes(test);
  FlipResult result;
  result.error_map = image::Image(w, h, 1);
  std::vector<float> exposure_error(reference.pixelCount());
  const double step = range.exposure_count > 1 ? (range.stop_exposure - range.start_exposure) /
                                                     (range.exposure_count - 1)
                                               : 0.0;
  for (int i = 0; i < range.exposure_count; ++i) {
    const double scale = std::exp2(range.start_exposure + i * step);
    const auto toneMap = [scale](float v) {
      // Exposed in double and limited, so that neither 2^exposure nor c² overflows a float;
      // the curve reaches its limit long before the bound.
      const float c = float(std::clamp(scale * double(v), -kToneMapInputBound, kToneMapInputBound));
      return (kAcesK0 * c * c + kAcesK1 * c) / (kAcesK3 * c * c + kAcesK4 * c + kAcesK5);
    };
    toOpponent(reference_rgb, toneMap, evaluator.reference());
    toOpponent(test_rgb, toneMap, evaluator.test());
    evaluator.evaluate(exposure_error.data());
    float* maximum = result.error_map.data().data();
    for (std::size_t p = 0; p < exposure_error.size(); ++p)
      maximum[p] = std::max(maximum[p], exposure_error[p]);
  }

  // Step 3: statistics of the maximum map.
  flip_detail::poolErrors(result);
  result.start_exposure = range.start_exposure;
  result.stop_exposure = range.stop_exposure;
  result.exposure_count = range.exposure_count;
  return result;
}

}  // namespace gib::metrics
