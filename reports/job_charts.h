// The chart-bearing sections of a job page besides its timings (reports/timing_sections.h):
// convergence on log-log axes with the fitted slope, and trends over recent runs. Each returns ""
// when the job has nothing to show for it.
#pragma once

#include "reports/html_report.h"
#include "results/results.h"

#include <string>

namespace gib::reports {

std::string convergenceSection(const results::JobResult& job, const std::string& primary_metric);

// Trends of the primary metric and the median frame time of the job over context.history (the
// run itself appended when the history does not end with it); shown from two runs on.
std::string trendsSection(const results::RunResults& results, const results::JobResult& job,
                          const ReportContext& context);

}  // namespace gib::reports
