#include "support/render_statistics.h"

#include "metrics/distributions.h"

#include <cmath>

namespace gib::test {

double imageMean(const image::Image& image) {
  double sum = 0;
  for (float v : image.data()) sum += v;
  return sum / double(image.data().size());
}

ImageMean imageMean(const ref::RenderResult& render) {
  double sum_variance = 0;
  const std::size_t pixels = render.mean.pixelCount();
  for (std::size_t p = 0; p < pixels; ++p) {
    double standard_error = 0;
    for (int c = 0; c < 3; ++c)
      standard_error += std::sqrt(double(render.variance.data()[3 * p + c])) / 3.0;
    sum_variance += standard_error * standard_error;
  }
  return {imageMean(render.mean), std::sqrt(sum_variance) / double(pixels)};
}

double familyWiseBound(const ref::RenderResult& render, double tests, double family_significance) {
  return metrics::studentTQuantile(1 - metrics::sidakSignificance(family_significance, tests) / 2,
                                   double(render.variance_dof));
}

}  // namespace gib::test
