// The image viewer of a job page (driven by reports/assets/viewer.js): two panes side by side or a
// wipe between them, sized to the window (a pane can fill it), each showing one layer (reference,
// image, difference, signed difference, relative error, FLIP map, the reference's standard
// error), synchronised zoom and pan, exposure and false colour on the linear values, error layers
// with colour bars of their values, and the values under the pointer. The linear values come from
// the job's viewer data (JobOutputs::viewer_data and reference_viewer_data, loaded with <script
// src> so the page opens from disk); the PNGs are in the page as well, for a run written before
// viewer data existed. Only outputs that exist when the report is written are offered: never a
// broken image.
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
