// index.html of a run's report: the run's facts, the comparison with the previous run (legend,
// then the regressed jobs first, with their reference, image and difference side by side), and
// the scene × technique matrix of thumbnails linking to the job pages.
#pragma once

#include "reports/run_comparison.h"
#include "results/results.h"

#include <filesystem>
#include <string>

namespace gib::reports {

// `run_dir` holds the outputs: a picture that is not there is left out rather than shown broken.
std::string indexPage(const std::filesystem::path& run_dir, const results::RunResults& results,
                      const RunComparison& comparison);

}  // namespace gib::reports
