// What `gibench run` and `gibench merge` print and write when a whole run is assembled: the HTML
// report, the CI outputs and the job table.
#pragma once

#include "cli/ci_outputs.h"
#include "suites/suite_runner.h"

#include <filesystem>

namespace gib::cli {

// The run's report, compared with the suite's earlier runs in the history database it was
// recorded in (none without one), and the CI outputs asked for (after the report they point to).
std::filesystem::path writeRunReport(const suites::RunOutcome& outcome,
                                     const suites::RunOptions& options, int trend_runs,
                                     const CiOutputs& ci);

// One line per job (primary metric, against the full reference, frame time, seconds; a failed
// job's failure), then where the results, history row, report and CI outputs are.
void printRunSummary(const suites::RunOutcome& outcome, const std::filesystem::path& report,
                     const CiOutputs& ci);

}  // namespace gib::cli
