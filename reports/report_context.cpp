#include "reports/report_context.h"

namespace gib::reports {

ReportContext loadReportContext(const results::HistoryDatabase& db,
                                const results::RunResults& results, std::size_t trend_runs) {
  ReportContext context;
  context.previous = db.previousRun(results.run.suite, results.run.started);
  context.history = db.recentRuns(results.run.suite, results.run.started, trend_runs);
  if (!context.history.empty() && context.history.size() == trend_runs &&
      context.history.back().run.id != results.run.id)
    context.history.erase(context.history.begin());
  return context;
}

}  // namespace gib::reports
