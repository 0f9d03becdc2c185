// `gibench diff --confirm`: a timing change settled on this machine, now. Each job whose frame
// time changed is rendered by the base build and the new build alternately (A B A B …), each run
// a fresh `gibench render` process with the job's own scene, parameters, size, frames and clock,
// and the per-run median frame times go to the paired test of results/timing_verdict.h.
// Alternating cancels what makes two separate runs differ: other tenants, clock frequency,
// caches. It costs 2 × pairs renders of each confirmed job.
#pragma once

#include "results/results.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace gib::suites {

struct ConfirmationOptions {
  // A/B runs of each build: the caller's choice (gibench diff: --pairs, else
  // metrics::recommendedPairs); fewer than two are refused.
  int pairs = 0;
  std::filesystem::path base_gibench, new_gibench;  // the builds of the two runs
  std::string gl_device;                            // empty: each build's default
  std::filesystem::path work_dir;                   // for the renders' files
  std::function<void(const std::string&)> log;      // progress, one line per run
};

struct InterleavedRuns {
  std::vector<double> base_ms, new_ms;  // per-run median frame times, pair by pair
};

// The `gibench render` arguments that time `job` as its run did (the job's technique, scene and
// parameters, size, frames, warm-up, iterations and clock), writing into `out_exr` and
// `timings_json`. Throws gib::InputError for a job that cannot be rendered alone (a reference
// job, a scene file the results do not locate).
std::vector<std::string> renderArguments(const results::JobResult& job,
                                         const std::string& gl_device,
                                         const std::filesystem::path& out_exr,
                                         const std::filesystem::path& timings_json);

// Renders `base_job` with the base build and `new_job` with the new build alternately,
// options.pairs times each. Throws std::runtime_error with the build's message when a render
// fails (a base build that does not know a parameter, say).
InterleavedRuns runInterleaved(const results::JobResult& base_job,
                               const results::JobResult& new_job,
                               const ConfirmationOptions& options);

}  // namespace gib::suites
