// The parameters both irradiance cache techniques take (accuracy, the placement's spacing and
// zone limits), declared once so that a suite sweeps them alike, and the settings they give.
#pragma once

#include "common/parameters.h"
#include "realtime/irradiance_cache/record_placement.h"
#include "realtime/technique.h"

#include <vector>

namespace gib::rt {

ParameterTable irradianceCacheParameters();
RecordPlacementSettings recordPlacementSettings(const ParameterValues& values);

// The statistics both techniques report alike (records, rounds, their time and rate), declared
// once, followed by each technique's own.
std::vector<DeclaredOutput> irradianceCacheStatistics(std::vector<DeclaredOutput> own);

}  // namespace gib::rt
