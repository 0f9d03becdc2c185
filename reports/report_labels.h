// Short labels and links the report's pages share: a job's sweep label, a run's short commit,
// parameter lists, the relative addresses of job pages and job outputs, what a reference is and
// which renderer the timings come from.
#pragma once

#include "results/results.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace gib::reports {

// The swept values of a job id ("cornell-direct/shadow=pcf,light_samples=4" →
// "shadow=pcf,light_samples=4"); empty for a job without sweeps.
std::string sweepLabel(const results::JobResult& job);

// "abc1234" (with "*" when the build was dirty), or "?" when the commit is unknown.
std::string shortCommit(const results::RunInfo& run);

// "shadow=pcf, light_samples=4"
std::string formatAssignments(const results::Assignments& assignments);

// A job page's file relative to the run directory: "report/<slug>.html".
std::string jobPageFile(const results::JobResult& job);

// An output path of JobOutputs (relative to the run directory, or absolute) as a link from a page
// `depth` directories below the run directory (0: index.html, 1: report/<slug>.html).
std::string outputHref(const std::string& path, int depth);

// Whether an output path (relative to the run directory, or absolute) names a file that is there:
// the report links and shows only those, never a broken link.
bool outputPresent(const std::filesystem::path& run_dir, const std::string& path);

// "file:///abs/path/index.html": the address a browser needs for a page of the report (Chromium
// keeps a "#…" fragment only on a file:/// URL, not on a bare path).
std::string fileUrl(const std::filesystem::path& path);

// Where a reference's camera rays sample each pixel (ReferenceUse::pixel_sampling), for people:
// "pixel centres" ("center") or "box-filtered over the pixel" ("area").
std::string pixelSamplingText(const std::string& sampling);

// The reference a number is measured against, short enough to stand beside it:
// "LE + LDE, pixel centres".
std::string referenceLabel(const results::ReferenceUse& use);

// A reference job's comparison: its last convergence checkpoint (the render its metrics measure)
// against the stored reference, "the 256-spp checkpoint against the 1024-spp reference"; empty
// for a job with no spp checkpoints.
std::string checkpointComparisonText(const results::JobResult& job);

// Whether a GL_RENDERER string names a software rasteriser (Mesa's llvmpipe, softpipe, swrast):
// its timings say nothing about a GPU's.
bool isSoftwareRasteriser(std::string_view renderer);

// The machine's state around a run or job, for people: "load 0.4 → 1.9 (1-minute average),
// governor performance, no other gibench process"; parts that were not readable are left out.
std::string conditionsText(const results::RunConditions& conditions);

}  // namespace gib::reports
