// The facts of the machine and build a run records (results.json "run"): enough to tell two runs'
// numbers apart when they came from different commits, builds, CPUs or GL implementations.
#pragma once

#include "results/results.h"

#include <string>

namespace gib::suites {

// Version, git commit and dirty flag, build type, host, CPU model and cores, Embree version.
// The GL fields stay empty: the runner fills them from the first technique job.
results::RunInfo describeEnvironment();

// Where the calling job runs: host, Slurm task (from its environment) and the time it waited in
// the queue (from kSubmittedAtVariable); the GL renderer is the caller's to fill in.
results::JobExecution describeJobExecution();

// Set by `gibench run --slurm` in its tasks' environment: the submission time, in seconds since
// the epoch, from which a task's queue wait is measured.
inline constexpr const char* kSubmittedAtVariable = "GIBENCH_SUBMITTED_AT";

// "2026-11-22T10:04:05Z" for now (UTC).
std::string utcTimestamp();

}  // namespace gib::suites
