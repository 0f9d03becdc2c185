// Statistics of reference renders for tests that know the true image: a grey render's image mean
// with its standard error, and the per-value bound a family-wise test needs.
#pragma once

#include "reference/progressive_renderer.h"

namespace gib::test {

struct ImageMean {
  double mean = 0;
  double standard_error = 0;
};

// The mean over all pixels of the channels' average. Pixels are independent, so its variance is
// Σ var / N²; the channels of one pixel are not (in a grey scene they are equal), so a pixel's
// variance is taken as the square of its channels' mean standard error, exact when they are
// equal and an upper bound otherwise.
ImageMean imageMean(const ref::RenderResult& render);

// The mean over all pixels of the channels' average of an RGB image.
double imageMean(const image::Image& image);

// The bound on |value − truth| / standard error that all of `tests` values keep with probability
// 1 − family_significance (Šidák), under Student's t with the render's degrees of freedom.
double familyWiseBound(const ref::RenderResult& render, double tests, double family_significance);

}  // namespace gib::test
