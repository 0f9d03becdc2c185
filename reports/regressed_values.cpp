#include "reports/regressed_values.h"

#include "reports/number_format.h"

#include <fmt/format.h>

namespace gib::reports {

std::vector<RegressedValue> regressedValues(const RunComparison& comparison) {
  std::vector<RegressedValue> values;
  if (!comparison.hasPrevious()) return values;
  const results::DiffReport& diff = *comparison.diff();
  for (const results::MetricChange& c : diff.metrics)
    if (c.verdict == results::Verdict::kRegressed)
      values.push_back({c.job, c.metric, formatNumber(c.base), formatNumber(c.next),
                        formatChange(c.relative_change),
                        fmt::format("±max({}, {}·|previous|)", formatNumber(c.tolerance.absolute),
                                    formatNumber(c.tolerance.relative)),
                        "", false});
  for (const results::TimingChange& c : diff.timings)
    if (c.verdict == results::Verdict::kRegressed)
      values.push_back({c.job, "median frame time (ms)", formatNumber(c.base_median_ms),
                        formatNumber(c.next_median_ms), formatChange(c.relative_change),
                        fmt::format("+{}", formatShare(c.tolerance.relative)), c.explanation(),
                        false});
  for (const results::JobPresence& p : diff.presence)
    if (p.verdict == results::Verdict::kMissing)
      values.push_back({p.job, "the job", "ran", "missing", "", "", "", true});
  return values;
}

}  // namespace gib::reports
