// What the HTML report compares a run with, read from the history database: the suite's previous
// run (for colouring) and its recent runs (for trends). Shared by `gibench report` and whatever
// writes a report at the end of `gibench run`.
#pragma once

#include "reports/html_report.h"
#include "results/history_db.h"

#include <cstddef>

namespace gib::reports {

// The newest run of the suite started before `results`, and the last `trend_runs` runs up to it
// (oldest first). When the database does not hold `results` itself, the report appends it to
// the trends, so one run fewer is read to keep the trend at `trend_runs` runs.
ReportContext loadReportContext(const results::HistoryDatabase& db,
                                const results::RunResults& results, std::size_t trend_runs);

}  // namespace gib::reports
