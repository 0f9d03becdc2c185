// Statistics for tests that know the true image or value: a grey render's image mean with its
// standard error, the mean of independent runs (seeds), the per-value bound a family-wise test
// needs under Student's t, and relMSE less the noise of the images compared.
#pragma once

#include "reference/path_tracer.h"
#include "reference/progressive_renderer.h"

#include <limits>
#include <vector>

namespace gib::test {

// An estimate of a mean with its standard error and the degrees of freedom of that error: the
// statistic (mean − truth) / standard_error follows Student's t with `dof` (the normal where it
// is infinite).
struct MeanEstimate {
  double mean = 0;
  double standard_error = 0;
  double dof = std::numeric_limits<double>::infinity();
};
using ImageMean = MeanEstimate;

// The mean over all pixels of the channels' average. Pixels are independent, so its variance is
// Σ var / N²; the channels of one pixel are not (in a grey scene they are equal), so a pixel's
// variance is taken as the square of its channels' mean standard error, exact when they are
// equal and an upper bound otherwise. Each pixel's variance has the render's degrees of freedom;
// their sum has the Welch–Satterthwaite degrees of freedom (Σ v)² / Σ (v² / dof), which grow
// with the pixels that carry the variance.
ImageMean imageMean(const ref::RenderResult& render);

// The mean over all pixels of the channels' average of an RGB image.
double imageMean(const image::Image& image);

// The mean of independent values (the image means of runs with different seeds, say), its
// standard error from their spread, and values − 1 degrees of freedom.
MeanEstimate sampleMean(const std::vector<double>& values);

// a − b for independent estimates: standard errors added in quadrature, degrees of freedom by
// Welch–Satterthwaite.
MeanEstimate difference(const MeanEstimate& a, const MeanEstimate& b);

// relMSE against the truth that `reference` estimates: the mean over pixels of the channels'
// ((t − r)² − Var r − Var t) / (r² + ε), ε = metrics::kRelativeEpsilon. E[(t − r)²] is the
// squared error of t against the truth plus the reference's variance (plus t's own where t is an
// estimate too: `test_variance`, the variance of each value of t, empty for a deterministic
// image), so this is an unbiased estimate of the squared error against the truth, which the
// plain relMSE overstates by the noise. Its standard error comes from the pixels' spread, and
// holds where the pixels' errors are independent (a deterministic image against a reference);
// it has pixels − 1 degrees of freedom.
MeanEstimate relMseLessNoise(const ref::RenderResult& reference, const image::Image& test,
                             const image::Image& test_variance = {});

// The relMSE that an error of `relative_error` × part in every value adds against `reference`:
// the mean over values of (relative_error · part)² / (r² + ε). An allowance for a technique whose
// known approximation errs by at most that fraction of a part of the light (its scattered part,
// say).
double relMseOfRelativeError(const image::Image& reference, const image::Image& part,
                             double relative_error);

// The mean red radiance of `samples` independent paths from `origin` along `direction` (no pixel
// filter: every path starts on the same ray), with its standard error and samples − 1 degrees of
// freedom. Each path is one replica of the sampler (seed 1234, pixel `pixel_id`), so the paths
// are independent and their spread gives the error.
MeanEstimate estimateRayRadiance(const ref::PathTracer& tracer, const glm::vec3& origin,
                                 const glm::vec3& direction, std::uint32_t samples,
                                 std::uint32_t pixel_id);

}  // namespace gib::test
