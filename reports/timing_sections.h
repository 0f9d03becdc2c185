// The timing sections of a job page: per pass, the reported clock's median and quartiles with
// the other clock's median beside them (GPU timer queries beside the CPU clock), each in one unit
// named in its heading (µs for a sub-millisecond table), a bar chart of the medians and a strip
// plot of every frame's time; then the upload, prepare and iterate phases. Passes never entered
// and phases that took no time get no row. Each returns "" when the job has nothing to show.
#pragma once

#include "reports/run_comparison.h"
#include "results/results.h"

#include <optional>
#include <string>

namespace gib::reports {

std::string timingsSection(const results::JobResult& job,
                           const std::optional<JobComparison>& compared);

// The per-pass time of each iteration of an iterative technique; empty when it has none.
std::string iterationTimingsSection(const results::JobResult& job);

}  // namespace gib::reports
