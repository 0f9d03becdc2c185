// The page of `gibench solid-angle-bench`: the bench test of hardware area-light sampling
// (Fournier & Péroche §6.1) as the paper's Figs. 7–9: error statistics per scheme and image size,
// the error over the receiving plane, and the median time of each phase.
#pragma once

#include "metrics/timing_statistics.h"

#include <string>
#include <utility>
#include <vector>

namespace gib::reports {

struct SolidAngleBenchRow {
  std::string scheme;  // occlusion_query, regular, jittered1, jittered4, jittered8
  int size = 0;        // pixels a side of the sampling image
  double mean_abs_error = 0, mean_error = 0, sd_error = 0, max_abs_error = 0;  // steradians
  double mean_exact = 0;
  // Each phase's milliseconds per point (count 0: not timed).
  metrics::TimingSummary render_ms, read_back_ms, weight_ms;
};

struct SolidAngleBenchFigure {
  std::string label;  // "regular, 48²"
  std::string png;    // file name beside the page
};

// The whole page; `facts` (program version, GL renderer, parameters) head it.
std::string solidAngleBenchPage(const std::vector<std::pair<std::string, std::string>>& facts,
                                const std::vector<SolidAngleBenchRow>& rows,
                                const std::vector<SolidAngleBenchFigure>& figures);

}  // namespace gib::reports
