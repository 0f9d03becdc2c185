// The parts of a figure suite's [[figure]] (results::FigureSpec) that its page, its composite PNG
// and the index share: where each panel's picture is, and the files a figure gives.
#pragma once

#include "results/results.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gib::reports {

// A panel's picture: the PNG of the chosen output of its job, or why there is none.
struct PanelPicture {
  const results::JobResult* job = nullptr;  // null when the run has no such job
  std::string path;    // relative to the run directory (or absolute); empty when absent
  std::string absent;  // why there is no picture (the page shows it in the panel's cell); empty
                       // when present
};

// An auxiliary image ("aux:atlas") is known only once the job ran, and a listed file may be gone
// from the run directory: either is reported in `absent`, never as a path to a missing file.
PanelPicture panelPicture(const std::filesystem::path& run_dir, const results::RunResults& results,
                          const results::FigureSpec::Panel& panel);

// The figure's jobs, each once, in panel order.
std::vector<std::string> figureJobs(const results::FigureSpec& figure);

// "report/figure-<name>.html" and "figures/<name>.png", relative to the run directory.
std::string figurePageFile(const results::FigureSpec& figure);
std::string figurePngFile(const results::FigureSpec& figure);

// Figure names become file names: throws gib::InputError for a name that is not one (a
// hand-edited results.json), a name used twice, or one whose page would be a job's page.
void checkFigureNames(const results::RunResults& results);

}  // namespace gib::reports
