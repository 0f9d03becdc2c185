// How a per-pixel error map is shown to people (compare --maps, the harness's report): false
// colour with a bar, over the range a person reads best for that metric.
#pragma once

#include "image/image.h"

#include <string>
#include <utility>

namespace gib::metrics {

// FLIP and SSIM have natural ranges [0, 1]; the other maps go from zero to their 99th
// percentile, so that one firefly does not hide the rest.
std::pair<float, float> errorMapDisplayRange(const std::string& metric, const image::Image& map);

// The map in false colour (magma) with its colour bar, ready for image::writePng.
image::Image errorMapForDisplay(const std::string& metric, const image::Image& map);

// |test − reference| of the luminance, one channel: the "amplified difference" of a report when
// shown through errorMapForDisplay (its range ends at the 99th percentile).
image::Image absoluteLuminanceDifference(const image::Image& reference, const image::Image& test);

}  // namespace gib::metrics
