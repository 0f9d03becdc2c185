// The source document's numbers beside ours ([[paper]] of a figure suite), as the job pages and
// the index show them.
#pragma once

#include "results/results.h"

#include <string>

namespace gib::reports {

// A table of the run's paper values with our value of each quantity and the ratio; with
// `job_id` only that job's rows, otherwise every row with a job column (links from the index).
// Empty when there are no rows.
std::string paperTable(const results::RunResults& results, const std::string* job_id);

}  // namespace gib::reports
