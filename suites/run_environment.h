// The facts of the machine and build a run records (results.json "run"): enough to tell two runs'
// numbers apart when they came from different commits, builds, CPUs or GL implementations.
#pragma once

#include "results/results.h"

#include <string>

namespace gib::suites {

// Version, git commit and dirty flag, build type, host, CPU model and cores, Embree version.
// The GL fields stay empty: the runner fills them from the first technique job.
results::RunInfo describeEnvironment();

// "2026-11-22T10:04:05Z" for now (UTC).
std::string utcTimestamp();

}  // namespace gib::suites
