// The parameters both irradiance cache techniques take (accuracy, the placement's spacing and
// zone limits), declared once so that a suite sweeps them alike, and the settings they give.
#pragma once

#include "common/parameters.h"
#include "realtime/irradiance_cache/record_placement.h"

namespace gib::rt {

ParameterTable irradianceCacheParameters();
RecordPlacementSettings recordPlacementSettings(const ParameterValues& values);

}  // namespace gib::rt
