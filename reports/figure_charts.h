// The figures of a figure suite ([[chart]], results::ChartSpec) drawn from a run's jobs: each
// chart's quantities looked up per job (reports/quantity.h), grouped into series, as SVG.
#pragma once

#include "reports/svg_charts.h"
#include "results/results.h"

#include <string>

namespace gib::reports {

// The points of one chart: the jobs its glob matches, in suite order, split by the series
// quantity's value in order of first appearance. Jobs without both numbers are left out.
SeriesPlot chartPlot(const results::RunResults& results, const results::ChartSpec& chart);

// The index page's "Figures" section with every chart of the run; empty when it has none.
std::string figuresSection(const results::RunResults& results);

}  // namespace gib::reports
