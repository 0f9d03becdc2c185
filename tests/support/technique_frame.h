// Renders as the technique tests do: one frame of a technique with the given `--set`
// assignments (no warm-up, GL debug output on so that any GL error fails the run, the Embree ray
// caster lent), and the reference of a path class to compare it with (seed 0: a fixed render).
#pragma once

#include "realtime/technique_runner.h"
#include "reference/progressive_renderer.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace gib::test {

// A 4 × 4 Lambertian floor (albedo 0.5) at y = 0 seen from straight above; lights are the
// caller's to add.
scene::Scene floorScene();

rt::TechniqueRunResult renderOneFrame(const scene::Scene& scene, const std::string& technique,
                                      const std::vector<std::string>& set, int size);

// `replicas` as ref::RenderSettings::replicas (0: the default, 4 for 64 spp and more): more give
// the variance layer more degrees of freedom at the same cost.
ref::RenderResult renderClassReference(const scene::Scene& scene, int size, std::uint32_t spp,
                                       scene::PathClass path_class, std::uint32_t replicas = 0);
// The same through the pixel centres (ref::PixelSampling::kCenter), what a harness job measures a
// technique against (docs/rendering.md, "Pixel sampling").
ref::RenderResult renderCentreClassReference(const scene::Scene& scene, int size, std::uint32_t spp,
                                             scene::PathClass path_class);

// The value of the statistic `name` among a run's or a technique's `statistics`; a test failure,
// and NaN (which no comparison passes), when there is none: a statistic that went missing must
// not read as 0.
double statisticNamed(const std::vector<rt::TechniqueStatistic>& statistics, std::string_view name);

// Each of `assignments` ("key=value") is refused when the technique's parameters are parsed, by
// an input error that names its key: a test failure for each that is accepted or not named.
void expectParametersRefused(const std::string& technique,
                             const std::vector<std::string>& assignments);

}  // namespace gib::test
