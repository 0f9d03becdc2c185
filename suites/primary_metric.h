// The metric a run is summarised by: relMSE when it was measured, else the first one. The index
// shows it (results::RunResults::primary_metric), the log's line of a finished job names it, and a
// convergence fit follows it, so that all three describe the number a reader compares.
#pragma once

#include "results/results.h"

#include <string>
#include <vector>

namespace gib::suites {

// Of one job's values: "relmse" when among them, else the first name; empty when there are none.
std::string primaryMetric(const results::NamedValues& values);

// Of a run: "relmse" when any job measured it, else the first job's first metric.
std::string primaryMetric(const std::vector<results::JobResult>& jobs);

}  // namespace gib::suites
