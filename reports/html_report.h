// The HTML report of a run: a directory of static pages that opens from disk with no network.
// Every page names the GL renderer its timings come from and flags a software rasteriser.
// index.html holds the run's facts and the scene × technique matrix (primary error metric against
// the named reference and, where the class is narrower, the full one; frame time, iterations'
// time and preparation per job, coloured against the previous run; the metric's legend from the
// registry); report/<slug>.html holds a page per job (reference, technique image, amplified
// difference and FLIP map to swap between, the rasteriser's disagreement mask, links to the
// full-precision files, metric tables with their references and legend, per-pass timing table on
// both clocks with bar chart and per-frame strip plot, convergence plot with its fitted metric
// and slope, the paper's numbers beside ours, trend charts over recent runs);
// report/figure-<name>.html a page per [[figure]] of a figure suite (reports/figure_page.h), and
// figures/ the standalone files for papers: each chart as SVG, each figure as PNG
// (reports/figure_files.h). Charts are inline SVG; styles and scripts are inline.
#pragma once

#include "results/results.h"

#include <filesystem>
#include <optional>
#include <vector>

namespace gib::reports {

struct ReportContext {
  std::optional<results::RunResults> previous;  // the suite's previous run, for colouring
  std::vector<results::RunResults> history;     // recent runs of the suite, oldest first (trends)
};

// Writes <run_dir>/index.html, <run_dir>/report/*.html and <run_dir>/figures/* for `results`,
// whose output paths are relative to run_dir. Atomic per file. Returns the path of index.html.
std::filesystem::path writeHtmlReport(const std::filesystem::path& run_dir,
                                      const results::RunResults& results,
                                      const ReportContext& context);

}  // namespace gib::reports
