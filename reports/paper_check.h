// Whether a run reproduces the source document's numbers: each [[paper]] value with a tolerance
// judged against ours. One judgement for the paper table (its "tolerance" column), `--junit` (a
// job with a value outside fails, type "paper") and `--summary` (the values outside).
#pragma once

#include "results/results.h"

#include <optional>
#include <string>
#include <vector>

namespace gib::reports {

enum class PaperVerdict {
  kShown,      // no tolerance: a number shown beside ours, not judged (times from other hardware)
  kWithin,     // |ours − paper| ≤ tolerance·|paper|
  kOutside,    // beyond it, ours not a number, or not measured by a job that ran
  kNotJudged,  // a tolerance, but the job is not in the run or failed (reported as such instead)
};

struct PaperCheck {
  const results::PaperValue* paper = nullptr;
  const results::JobResult* job = nullptr;  // null when the run lacks the job
  std::optional<double> ours;               // nullopt when not measured
  PaperVerdict verdict = PaperVerdict::kShown;
};

// `paper` must outlive the result (it points into it), as must the job it names in `results`.
PaperCheck checkPaperValue(const results::RunResults& results, const results::PaperValue& paper);

// Every [[paper]] value of the run, in suite order.
std::vector<PaperCheck> checkPaperValues(const results::RunResults& results);

// A relative tolerance as people read it: 0.05 → "±5%", 0.025 → "±2.5%".
std::string toleranceLabel(double tolerance);

// "within ±5%", "outside ±5%", "not measured (±5%)", "±5% (not judged: the job failed)";
// empty for a value without a tolerance.
std::string paperVerdictText(const PaperCheck& check);

}  // namespace gib::reports
