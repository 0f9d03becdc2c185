#include "reports/paper_check.h"

#include "reports/number_format.h"
#include "results/quantity.h"

#include <cmath>

namespace gib::reports {

PaperCheck checkPaperValue(const results::RunResults& results, const results::PaperValue& paper) {
  PaperCheck check;
  check.paper = &paper;
  check.job = results.findJob(paper.job);
  if (check.job) check.ours = results::quantityValue(*check.job, paper.quantity);
  if (!paper.tolerance) return check;
  // A failed or absent job has its own verdict (an error, a missing or skipped job): judging its
  // paper values as well would count one problem twice.
  if (!check.job || check.job->failed()) {
    check.verdict = PaperVerdict::kNotJudged;
    return check;
  }
  // NaN compares false, so a NaN of ours is outside, as is a value not measured at all.
  const bool within =
      check.ours && std::abs(*check.ours - paper.value) <= *paper.tolerance * std::abs(paper.value);
  check.verdict = within ? PaperVerdict::kWithin : PaperVerdict::kOutside;
  return check;
}

std::vector<PaperCheck> checkPaperValues(const results::RunResults& results) {
  std::vector<PaperCheck> checks;
  checks.reserve(results.paper.size());
  for (const results::PaperValue& paper : results.paper)
    checks.push_back(checkPaperValue(results, paper));
  return checks;
}

std::string toleranceLabel(double tolerance) {
  return "±" + formatNumber(100 * tolerance, 3) + "%";
}

std::string paperVerdictText(const PaperCheck& check) {
  if (!check.paper->tolerance) return {};
  const std::string label = toleranceLabel(*check.paper->tolerance);
  switch (check.verdict) {
    case PaperVerdict::kWithin:
      return "within " + label;
    case PaperVerdict::kOutside:
      return check.ours ? "outside " + label : "not measured (" + label + ")";
    case PaperVerdict::kNotJudged:
      return label + (check.job ? " (not judged: the job failed)"
                                : " (not judged: the job is not in this run)");
    case PaperVerdict::kShown:
      break;
  }
  return {};
}

}  // namespace gib::reports
