// A run as JUnit XML (`--junit FILE`), the test report format that GitLab, Jenkins and GitHub's
// test reporters read, so a CI pipeline shows which jobs regressed without opening the report:
//
//   <testsuites name tests failures errors time>
//     <testsuite name=<suite> tests failures errors skipped time timestamp hostname>
//       <properties> run_id, suite_file, commit, git_dirty, gibench_version, previous_run_id,
//                    previous_commit, report </properties>
//       <testcase classname="<suite>.<scene>.<technique>" name="<job id>" time="<job seconds>">
//         <failure message type>…</failure> | <error …>…</error> | <skipped message/>
//         <system-out>primary metric, frame time, the job's report page</system-out>
//
// Verdicts (docs/harness.md, "CI outputs"): a job fails, type "regression", when it regressed
// against the suite's previous run exactly as the report colours it (RunComparison: a metric
// beyond tolerance, a timing the evidence confirms; an unconfirmed timing change does not fail);
// type "paper" when one of its [[paper]] values is outside its tolerance (reports/paper_check.h);
// both at once read "regression" and list both. A job that failed to run is an <error>. A job of
// the previous run that this one lacks is a failed test case of type "missing", and one that a
// partial run (--only) left out is <skipped>.
#pragma once

#include "reports/run_comparison.h"
#include "results/results.h"

#include <filesystem>
#include <string>

namespace gib::reports {

// `run_dir` prefixes the report pages named in <system-out> (empty: relative to the run
// directory). `previous`, when given, names the classname of a missing job by its scene and
// technique; without it a missing job's classname is the suite's name.
std::string junitReport(const results::RunResults& results, const RunComparison& comparison,
                        const std::filesystem::path& run_dir,
                        const results::RunResults* previous = nullptr);

}  // namespace gib::reports
