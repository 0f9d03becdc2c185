// Private to gib_reports: a HistoryFilter as the WHERE clause of the history database's queries,
// with every value a bound parameter.
#pragma once

#include "results/history_db.h"

#include <string>
#include <vector>

namespace gib::results::detail {

struct SqlCondition {
  std::string where;                    // " WHERE …", or empty when nothing is filtered
  std::vector<std::string> parameters;  // text parameters, in order
};

// Runs `r` matching the suite, commit and date bounds, and, when the filter names a scene,
// technique or job, having such a job. Throws gib::InputError for a malformed date bound.
SqlCondition runCondition(const HistoryFilter& filter);

// Metric values `m` of runs `r` matching the whole filter (metric, scene, technique, job, and
// the run conditions above).
SqlCondition valueCondition(const HistoryFilter& filter);

}  // namespace gib::results::detail
