// The regressed values of a run against the suite's previous run, one row per quantity, formatted
// for people: what `--junit` puts in a failed test case and `--summary` in its table. Taken from
// RunComparison's diff, so they are exactly what the report colours red.
#pragma once

#include "reports/run_comparison.h"

#include <string>
#include <vector>

namespace gib::reports {

struct RegressedValue {
  std::string job;
  std::string quantity;  // "relmse", "full:relmse", "median frame time (ms)", "the job"
  std::string previous, next, change;  // "0.001", "0.0021", "+110.0%"
  std::string allowed;                 // "±max(0, 0.05·|previous|)", "+10.0%"
  std::string evidence;  // a timing's: what its verdict rests on (TimingChange::explanation)
  bool missing = false;  // the job of the previous run is not in this one
};

// Metrics, then timings, then missing jobs, each in the diff's order (the previous run's job
// order); empty without a previous run. Unconfirmed timing changes are not regressions.
std::vector<RegressedValue> regressedValues(const RunComparison& comparison);

}  // namespace gib::reports
