// A run in a few lines of Markdown for a pull-request comment (`--summary FILE`): a headline with
// the counts (jobs, regressions, improvements, failed jobs, paper values out of tolerance), the
// regressions as a table (job, quantity, previous, this run, change, allowed), the failed jobs
// with their reasons, the paper values out of tolerance, and for the first regressed jobs their
// pictures (reference, image, difference) and the report's index. Nothing to report reads
// "no regressions" plainly. The verdicts are the report's and `--junit`'s (docs/harness.md,
// "CI outputs").
#pragma once

#include "reports/run_comparison.h"
#include "results/results.h"

#include <cstddef>
#include <filesystem>
#include <string>

namespace gib::reports {

// Regressed jobs whose pictures the summary links: a comment stays readable.
inline constexpr std::size_t kSummaryPictureJobs = 6;

// Picture links and the index are relative to the run directory (job outputs are), and the
// summary says so, naming `run_dir`; a CI job that publishes the run directory as an artifact, or
// a comment posted from it, resolves them there.
std::string markdownSummary(const results::RunResults& results, const RunComparison& comparison,
                            const std::filesystem::path& run_dir);

}  // namespace gib::reports
