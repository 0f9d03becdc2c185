// The page of a figure suite's [[figure]] (report/figure-<name>.html): the document's figure
// rebuilt from the run, its panels in the declared grid, each with its picture, caption, number
// and job, the figure's caption, and beside it the paper's values and the suite's charts of the
// figure's jobs, with links to the standalone files (figures/<name>.png and the charts' SVGs).
#pragma once

#include "results/results.h"

#include <filesystem>
#include <string>

namespace gib::reports {

// The page's HTML. `run_dir` holds the outputs (a panel whose picture is not there shows a note
// saying why, never a broken image) and figures/, whose files are linked only when present.
std::string figurePage(const std::filesystem::path& run_dir, const results::RunResults& results,
                       const results::FigureSpec& figure);

// The number printed under a panel: "<quantity label>: <value>[ ms]", "… : not measured" when
// the job lacks it, empty for metric "none" (or no metric and no primary metric).
std::string panelValueText(const results::RunResults& results, const results::JobResult* job,
                           const std::string& metric);

}  // namespace gib::reports
