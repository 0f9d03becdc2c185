// A run directory as `gibench run` leaves it, made without rendering, for the report tests and
// benchmarks: small PNGs under jobs/<slug>/ and results covering every part of a report.
#pragma once

#include "image/image.h"
#include "results/results.h"

#include <filesystem>
#include <string>

namespace gib::test {

// Per-pass timings of a frame with nested passes (g-buffer; shadow maps with a cube child;
// shading), every per-frame sample included, on the CPU clock. `scale` multiplies every time;
// `root` is "frame" or "iteration".
metrics::PassTimings nestedPassTimings(double scale = 1.0, int frames = 8,
                                       const std::string& root = "frame");

// A technique job on cornell with metrics against the class and the full reference, nested pass
// timings, a convergence series over iterations with its fit, and the given output files
// (jobs/<slug>/…; not written here).
results::JobResult syntheticTechniqueJob(const std::string& sweep, double relmse,
                                         double frame_scale = 1.0);

// The run of three jobs (run id `run_id`, commit `commit`): the Cornell reference (no timings,
// no FLIP map, convergence over spp), `direct` with shadow=pcf (every output, paper values for
// relmse and the frame) and `direct` with shadow=vsm (a two-point convergence, so no interval);
// two charts and a 2 × 2 figure "fig-shadows" of the first two jobs (one panel names an auxiliary
// image its job lacks). Auxiliary images are written 16 × 16, the others 32 × 24.
results::RunResults syntheticReportResults(
    const std::string& run_id = "20261122-100405-smoke-1a2b3c4d",
    const std::string& commit = "0123456789abcdef");

// Writes the PNGs every job of `results` lists (a few pixels each) under `run_dir`, and the
// viewer data (image/viewer_data.h) of syntheticViewerImage's layers.

void writeSyntheticOutputs(const std::filesystem::path& run_dir,
                           const results::RunResults& results);

// A run directory as `gibench report` reads it: writeSyntheticOutputs and results.json under
// `run_dir` (created), with the run's store set to `store` (where no history database is).
void writeSyntheticRunDirectory(const std::filesystem::path& run_dir, results::RunResults& results,
                                const std::filesystem::path& store);

// Makes `job` a job that failed to run with `reason`: no metrics and no timings, as a merge
// records it.
void markFailed(results::JobResult& job, const std::string& reason);

// The linear layer `layer` ("image", "reference", "stderr": RGB; "flip": one channel) of a
// synthetic job's viewer data, with values exactly representable as half floats; "thumbnail"
// is the image as well.
image::Image syntheticViewerImage(const results::JobResult& job, const std::string& layer);

}  // namespace gib::test
