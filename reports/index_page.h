// index.html of a run's report: the run's facts, the comparison with the previous run (legend
// and regressions), and the scene × technique matrix linking to the job pages.
#pragma once

#include "reports/run_comparison.h"
#include "results/results.h"

#include <string>

namespace gib::reports {

std::string indexPage(const results::RunResults& results, const RunComparison& comparison);

}  // namespace gib::reports
