// The bench test of Fournier & Péroche §6.1: a square light partly hidden by a square occluder
// above a receiving plane; at a grid of points on the plane each sampling scheme estimates the
// light's visible solid angle, which is compared with the exact value
// (scene/polygon_solid_angle.h). Gives the paper's Fig. 7 (mean, standard deviation and maximum
// error per scheme and image size), Fig. 8 (the error over the plane) and Fig. 9 (median time of
// each phase).
#pragma once

#include "realtime/techniques/jittered_light_sampling/light_coverage_sampler.h"
#include "scene/occluded_light_bench.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <functional>
#include <vector>

namespace gib::rt {

// A quad's two triangles (corners 0 1 2 and 0 2 3), as the sampler takes them.
std::vector<glm::vec3> quadTriangles(const std::vector<glm::dvec3>& quad);

struct SchemeMeasurement {
  CoverageSettings settings;
  // Per point (scene::occludedLightBenchPoints' order): estimate − exact, in steradians.
  std::vector<double> errors;
  double mean_abs_error = 0;
  double mean_error = 0;  // signed: the scheme's bias, averaged over the plane
  double sd_error = 0;    // standard deviation of the signed error over the plane
  double max_abs_error = 0;
  double mean_exact = 0;  // the mean exact visible solid angle, for scale
  // Each timed point's phases (the first pass over the points and further passes as needed), for
  // medians: the paper reports medians, being unable to keep other threads from running during a
  // measurement.
  std::vector<CoveragePhaseTimes> phase_times;
};

// Runs one scheme over the bench's points; `progress` is called with points done. Needs a current
// GL context.
SchemeMeasurement measureScheme(const scene::OccludedLightBench& bench,
                                const CoverageSettings& settings, std::size_t timing_samples,
                                const std::function<void(std::size_t)>& progress = {});

}  // namespace gib::rt
