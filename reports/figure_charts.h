// The figures of a figure suite ([[chart]], results::ChartSpec) drawn from a run's jobs: each
// chart's quantities looked up per job (reports/quantity.h), grouped into series, as SVG.
#pragma once

#include "reports/svg_charts.h"
#include "results/results.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gib::reports {

// The points of one chart: the jobs its glob matches, in suite order, split by the series
// quantity's value in order of first appearance. Jobs without both numbers are left out.
SeriesPlot chartPlot(const results::RunResults& results, const results::ChartSpec& chart);

// The chart as a standalone SVG document (an XML declaration, then the <svg> root with its
// namespace), for a paper or a pull request: figures/<slug>.svg.
std::string standaloneChartSvg(const results::RunResults& results, const results::ChartSpec& chart);

// The file name (without ".svg") of each chart's standalone SVG, in chart order: the title in
// lower case with every run of other characters than letters and digits as one '-' ("Fig. 6:
// error" -> "fig-6-error"), at most 80 characters, "-2", "-3" … after a name already given, and
// "chart-<n>" for a title without letters or digits.
std::vector<std::string> chartSlugs(const std::vector<results::ChartSpec>& charts);

// figures/<slug>.svg of the chart at `index` of results.charts, relative to the run directory.
std::string chartSvgFile(const results::RunResults& results, std::size_t index);

// The index page's "Figures" section: a link to each figure's page with a preview (its first
// panel's picture that is in `run_dir`), every chart of the run and the paper's values; empty
// when the run has none of them.
std::string figuresSection(const std::filesystem::path& run_dir,
                           const results::RunResults& results);

}  // namespace gib::reports
