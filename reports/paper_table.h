// The source document's numbers beside ours ([[paper]] of a figure suite), as the job pages and
// the index show them.
#pragma once

#include "results/results.h"

#include <set>
#include <string>

namespace gib::reports {

// A table of the run's paper values with our value of each quantity and the ratio; with
// `job_id` only that job's rows, otherwise every row with a job column (links from the index).
// Empty when there are no rows.
std::string paperTable(const results::RunResults& results, const std::string* job_id);

// The rows of the jobs in `jobs`, with a job column linking to their pages from a page `depth`
// directories below the run directory (1: report/figure-<name>.html).
std::string paperTable(const results::RunResults& results, const std::set<std::string>& jobs,
                       int depth);

}  // namespace gib::reports
