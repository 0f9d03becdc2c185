#include "support/render_statistics.h"

#include "metrics/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gib::test {

double imageMean(const image::Image& image) {
  double sum = 0;
  for (float v : image.data()) sum += v;
  return sum / double(image.data().size());
}

ImageMean imageMean(const ref::RenderResult& render) {
  double sum_variance = 0, sum_squared_variance = 0;
  const std::size_t pixels = render.mean.pixelCount();
  for (std::size_t p = 0; p < pixels; ++p) {
    double standard_error = 0;
    for (int c = 0; c < 3; ++c)
      standard_error += std::sqrt(double(render.variance.data()[3 * p + c])) / 3.0;
    const double variance = standard_error * standard_error;
    sum_variance += variance;
    sum_squared_variance += variance * variance;
  }
  const double dof = sum_squared_variance > 0 ? sum_variance * sum_variance /
                                                    (sum_squared_variance / render.variance_dof)
                                              : double(render.variance_dof);
  return {imageMean(render.mean), std::sqrt(sum_variance) / double(pixels), dof};
}

MeanEstimate sampleMean(const std::vector<double>& values) {
  if (values.size() < 2) throw std::invalid_argument("sampleMean needs two values or more");
  const double n = double(values.size());
  double mean = 0, squares = 0;
  for (double v : values) mean += v / n;
  for (double v : values) squares += (v - mean) * (v - mean);
  return {mean, std::sqrt(squares / (n - 1) / n), n - 1};
}

MeanEstimate difference(const MeanEstimate& a, const MeanEstimate& b) {
  const double va = a.standard_error * a.standard_error;
  const double vb = b.standard_error * b.standard_error;
  // A term with infinite degrees of freedom contributes nothing to the denominator.
  const double denominator =
      (std::isinf(a.dof) ? 0 : va * va / a.dof) + (std::isinf(b.dof) ? 0 : vb * vb / b.dof);
  return {a.mean - b.mean, std::sqrt(va + vb),
          denominator > 0 ? (va + vb) * (va + vb) / denominator
                          : std::numeric_limits<double>::infinity()};
}

MeanEstimate relMseLessNoise(const ref::RenderResult& reference, const image::Image& test,
                             const image::Image& test_variance) {
  metrics::requireComparable(reference.mean, test);
  if (reference.variance.data().size() != test.data().size())
    throw std::invalid_argument("relMseLessNoise needs the reference's variance layer");
  const bool stochastic = !test_variance.data().empty();
  const std::size_t pixels = test.pixelCount();
  double sum = 0, squares = 0;
  for (std::size_t p = 0; p < pixels; ++p) {
    double term = 0;  // the pixel's mean over its channels
    for (std::size_t i = 3 * p; i < 3 * p + 3; ++i) {
      const double r = reference.mean.data()[i], d = test.data()[i] - r;
      const double noise =
          reference.variance.data()[i] + (stochastic ? test_variance.data()[i] : 0);
      term += (d * d - noise) / (r * r + metrics::kRelativeEpsilon) / 3;
    }
    sum += term;
    squares += term * term;
  }
  const double n = double(pixels), mean = sum / n;
  return {mean, std::sqrt((squares / n - mean * mean) / (n - 1)), n - 1};
}

double relMseOfRelativeError(const image::Image& reference, const image::Image& part,
                             double relative_error) {
  metrics::requireComparable(reference, part);
  double sum = 0;
  for (std::size_t i = 0; i < reference.data().size(); ++i) {
    const double r = reference.data()[i], e = relative_error * part.data()[i];
    sum += e * e / (r * r + metrics::kRelativeEpsilon);
  }
  return sum / double(reference.data().size());
}

MeanEstimate estimateRayRadiance(const ref::PathTracer& tracer, const glm::vec3& origin,
                                 const glm::vec3& direction, std::uint32_t samples,
                                 std::uint32_t pixel_id) {
  double sum = 0, sum_squares = 0;
  for (std::uint32_t s = 0; s < samples; ++s) {
    ref::PathSampler sampler(1234, pixel_id, s, samples);
    const double r = tracer.radiance(origin, direction, sampler).total.r;
    sum += r;
    sum_squares += r * r;
  }
  MeanEstimate e;
  e.mean = sum / samples;
  const double variance = (sum_squares - samples * e.mean * e.mean) / (samples - 1);
  e.standard_error = std::sqrt(std::max(variance, 0.0) / samples);
  e.dof = samples - 1;
  return e;
}

}  // namespace gib::test
