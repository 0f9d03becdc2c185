// report/<slug>.html: one job's page: its facts, the metric tables against the class and the full
// reference, the image viewer, timings, convergence, the paper's numbers beside ours and trends.
#pragma once

#include "reports/html_report.h"
#include "reports/run_comparison.h"
#include "results/results.h"

#include <filesystem>
#include <string>

namespace gib::reports {

std::string jobPage(const std::filesystem::path& run_dir, const results::RunResults& results,
                    const results::JobResult& job, const RunComparison& comparison,
                    const ReportContext& context);

}  // namespace gib::reports
