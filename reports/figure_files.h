// The standalone files of a figure suite's run, for papers and pull requests, in figures/ of the
// run directory: every [[chart]] as an SVG document and every [[figure]] as one PNG.
#pragma once

#include "results/results.h"

#include <filesystem>

namespace gib::reports {

// Writes figures/<slug>.svg for every chart (reports/figure_charts.h, chartSlugs) and
// figures/<name>.png for every figure with a picture (reports/figure_composite.h). Atomic per
// file; nothing (not even the folder) for a run without charts and figures.
void writeFigureFiles(const std::filesystem::path& run_dir, const results::RunResults& results);

}  // namespace gib::reports
