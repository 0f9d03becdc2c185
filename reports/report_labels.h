// Short labels and links the report's pages share: a job's sweep label, a run's short commit,
// parameter lists, and the relative addresses of job pages and job outputs.
#pragma once

#include "results/results.h"

#include <string>

namespace gib::reports {

// The swept values of a job id ("cornell-direct/shadow=pcf,light_samples=4" →
// "shadow=pcf,light_samples=4"); empty for a job without sweeps.
std::string sweepLabel(const results::JobResult& job);

// "abc1234" (with "*" when the build was dirty), or "?" when the commit is unknown.
std::string shortCommit(const results::RunInfo& run);

// "shadow=pcf, light_samples=4"
std::string formatAssignments(const results::Assignments& assignments);

// A job page's file relative to the run directory: "report/<slug>.html".
std::string jobPageFile(const results::JobResult& job);

// An output path of JobOutputs (relative to the run directory, or absolute) as a link from a page
// `depth` directories below the run directory (0: index.html, 1: report/<slug>.html).
std::string outputHref(const std::string& path, int depth);

// The machine's state around a run or job, for people: "load 0.4 → 1.9 (1-minute average),
// governor performance, no other gibench process"; parts that were not readable are left out.
std::string conditionsText(const results::RunConditions& conditions);

}  // namespace gib::reports
