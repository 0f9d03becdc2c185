// The run-to-run record of each job's timing: the per-run medians of comparable earlier runs from
// the history database, the evidence `gibench diff` weighs a timing change against. Two runs of
// one commit minutes apart differ by more than the frames within a run vary (other tenants, clock
// frequency, caches, the software rasterizer's thread scheduling), so only the spread between
// runs says whether a change is larger than the machine's own drift.
#pragma once

#include "results/history_db.h"
#include "results/results.h"

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace gib::results {

// A job's per-run medians (JobResult::runMedianMs), oldest first.
using TimingHistory = std::map<std::string, std::vector<double>>;

// Whether `run`'s `job` measured the same thing as `reference`'s on the same kind of machine:
// same host, GL renderer and build type; same scene, technique, parameters, size, frame counts
// and timing clock; as many repeats.
bool comparableTiming(const RunInfo& run, const JobResult& job, const RunInfo& reference_run,
                      const JobResult& reference);

// The history of every timed job of `next` from `runs` (any order), leaving out `base` and `next`
// themselves and runs that started after the later of the two: only runs that could have been
// seen when the newer one was made.
TimingHistory timingHistoryOf(const std::vector<RunResults>& runs, const RunResults& base,
                              const RunResults& next);

// The same from the last `max_runs` runs of `next`'s suite in a history database.
TimingHistory loadTimingHistory(const HistoryDatabase& db, const RunResults& base,
                                const RunResults& next, std::size_t max_runs = 30);

}  // namespace gib::results
