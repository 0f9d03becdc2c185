#include "realtime/techniques/jittered_light_sampling/solid_angle_bench.h"

#include "scene/polygon_solid_angle.h"

#include <algorithm>
#include <cmath>

namespace gib::rt {

namespace {}  // namespace

std::vector<glm::vec3> quadTriangles(const std::vector<glm::dvec3>& q) {
  return {glm::vec3(q[0]), glm::vec3(q[1]), glm::vec3(q[2]),
          glm::vec3(q[0]), glm::vec3(q[2]), glm::vec3(q[3])};
}

SchemeMeasurement measureScheme(const scene::OccludedLightBench& bench,
                                const CoverageSettings& settings, std::size_t timing_samples,
                                const std::function<void(std::size_t)>& progress) {
  SchemeMeasurement m;
  m.settings = settings;
  LightCoverageSampler sampler(quadTriangles(bench.light), quadTriangles(bench.occluder), settings);
  const std::vector<glm::dvec3> points = scene::occludedLightBenchPoints(bench);
  const std::size_t total = std::max(timing_samples, points.size());
  for (std::size_t i = 0; i < total; ++i) {
    const std::size_t p = i % points.size();
    CoveragePhaseTimes t;
    // Later passes draw new jitter (the point's index keeps counting), as a progressive
    // renderer resampling a point would.
    const double estimate = sampler.visibleSolidAngle(points[p], std::uint32_t(i), &t);
    if (i < timing_samples) m.phase_times.push_back(t);
    if (i < points.size()) {
      const double exact = scene::visibleSolidAngle(points[p], bench.light, bench.occluder);
      m.errors.push_back(estimate - exact);
      m.mean_exact += exact / double(points.size());
    }
    if (progress) progress(i + 1);
  }
  const double n = double(m.errors.size());
  for (double e : m.errors) {
    m.mean_abs_error += std::abs(e) / n;
    m.mean_error += e / n;
    m.max_abs_error = std::max(m.max_abs_error, std::abs(e));
  }
  double squares = 0;
  for (double e : m.errors) squares += (e - m.mean_error) * (e - m.mean_error);
  m.sd_error = n > 1 ? std::sqrt(squares / (n - 1)) : 0;
  return m;
}

}  // namespace gib::rt
