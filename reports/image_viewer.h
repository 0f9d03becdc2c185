// The image viewer of a job page: the class reference, the job's image, the amplified difference
// and the FLIP map (with its colour bar), one shown at a time; buttons choose one, and hovering
// the image swaps between the reference and the job's image. Only outputs that exist when the
// report is written are shown: a job without a FLIP map (or a reference job without a separate
// reference picture) simply has fewer buttons, never a broken image.
#pragma once

#include "results/results.h"

#include <filesystem>
#include <string>

namespace gib::reports {

// HTML for a page one directory below the run directory (report/<slug>.html).
std::string imageViewer(const std::filesystem::path& run_dir, const results::JobResult& job);

// The technique's auxiliary images (a radiance atlas, one bounce's contribution) side by side
// with their descriptions; empty when the job has none. Same page depth as imageViewer.
std::string auxiliaryImages(const std::filesystem::path& run_dir, const results::JobResult& job);

}  // namespace gib::reports
